#!/usr/bin/python3
"""dlfl view in a real browser: headless Chromium opens the page the tool wrote, draws it with its own WebGL
(software, SwiftShader) and takes screenshots, which this script decodes with a PNG reader of its own (zlib and
the five PNG filters, nothing of dlfl's) and measures:

- the unit cube [-1, 1]^3 seen front-on through an orthographic camera covers the square that the viewer's
  fit predicts (docs/viewer.md, "Camera"): side = H / (1.1 * sqrt(3)) pixels on an H-pixel-high window,
  area within 2%;
- the slider's step 2 (Catmull-Clark, two steps) changes the picture: fewer covered pixels (the limit surface
  lies strictly inside the cube, so its outline does too), and the page's step label says M_2.

Usage: view_in_chromium.py DLFL_TOOL SOURCE_DIR SCRATCH_DIR. Chromium missing is a failure, not a skip: CI
installs it (.ci/run).
"""
import math
import os
import shutil
import struct
import subprocess
import sys
import zlib
from concurrent.futures import ThreadPoolExecutor

WIDTH, HEIGHT = 400, 300
# What works on Debian 12's chromium here and in CI (docs/viewer.md, "Testing"): the new headless mode, no
# sandbox (CI runs as root), WebGL on the SwiftShader software renderer through ANGLE.
CHROMIUM_FLAGS = ["--headless", "--no-sandbox", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
                  "--no-first-run", "--disable-extensions", "--disable-background-networking",
                  "--disable-component-update", "--disable-sync", "--mute-audio", "--hide-scrollbars"]


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def decode_png(data):
    """(width, height, rows of (r, g, b) tuples) of an 8-bit RGB or RGBA PNG."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        fail("the screenshot is not a PNG")
    at, idat, header = 8, b"", None
    while at < len(data):
        length, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + length]
        at += 12 + length
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        elif kind == b"IEND":
            break
    width, height, depth, color_type, _, _, interlace = header
    if depth != 8 or color_type not in (2, 6) or interlace != 0:
        fail("unexpected PNG layout: depth %d, colour type %d, interlace %d" % (depth, color_type, interlace))
    channels = 3 if color_type == 2 else 4
    stride = width * channels
    raw = zlib.decompress(idat)
    rows, previous = [], bytearray(stride)
    for y in range(height):
        filter_type = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            left = line[i - channels] if i >= channels else 0
            up = previous[i]
            up_left = previous[i - channels] if i >= channels else 0
            if filter_type == 1:
                line[i] = (line[i] + left) & 255
            elif filter_type == 2:
                line[i] = (line[i] + up) & 255
            elif filter_type == 3:
                line[i] = (line[i] + (left + up) // 2) & 255
            elif filter_type == 4:
                p = left + up - up_left
                pa, pb, pc = abs(p - left), abs(p - up), abs(p - up_left)
                line[i] = (line[i] + (left if pa <= pb and pa <= pc else up if pb <= pc else up_left)) & 255
            elif filter_type != 0:
                fail("unknown PNG filter %d" % filter_type)
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return width, height, rows


def distance(a, b):
    return sum(abs(x - y) for x, y in zip(a, b))


def covered_pixels(rows, background, face):
    """Pixels nearer the face's colour than the background's: anti-aliased border pixels count when they are
    more than half covered, so the count is the covered area to within a fraction of the outline."""
    return sum(1 for row in rows for p in row if distance(p, face) < distance(p, background))


def screenshot(chromium, page, fragment, scratch, name):
    """Opens page#fragment in its own profile; returns the PNG's pixels and the page's DOM after its scripts."""
    png = os.path.join(scratch, name + ".png")
    if os.path.exists(png):
        os.remove(png)
    run = subprocess.run([chromium] + CHROMIUM_FLAGS + [
        "--user-data-dir=" + os.path.join(scratch, "profile-" + name), "--window-size=%d,%d" % (WIDTH, HEIGHT),
        "--screenshot=" + png, "--dump-dom", "file://" + page + "#" + fragment],
        capture_output=True, text=True, timeout=120)
    if run.returncode != 0 or not os.path.exists(png):
        fail("chromium made no screenshot of %s (exit %d):\n%s" % (fragment, run.returncode, run.stderr[-2000:]))
    with open(png, "rb") as f:
        return decode_png(f.read()), run.stdout


def main():
    tool, source, scratch = sys.argv[1:4]
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        fail("chromium is not installed: the browser test needs Debian's chromium package "
             "(apt-get install chromium; .ci/run installs it)")
    os.makedirs(scratch, exist_ok=True)
    page = os.path.abspath(os.path.join(scratch, "cube.html"))
    made = subprocess.run([tool, "view", os.path.join(source, "data", "cube.obj"), "-s", "catmull-clark", "-n", "2",
                           "-o", page], capture_output=True, text=True)
    if made.returncode != 0:
        fail("dlfl view failed: " + made.stderr)

    views = {"step0": "view=front&ortho=1&edges=0&ui=0&step=0", "step2": "view=front&ortho=1&edges=0&ui=0&step=2"}
    with ThreadPoolExecutor(2) as pool:  # two browsers at once: the test's time is one browser's start
        shots = dict(zip(views, pool.map(lambda n: screenshot(chromium, page, views[n], scratch, n), views)))

    (width, height, rows), _ = shots["step0"]
    background = rows[0][0]
    face = rows[height // 2][width // 2]
    if distance(face, background) < 60:
        fail("nothing drawn at the window's centre (colour %s, background %s): no WebGL?" % (face, background))
    side = min(width, height) / (1.1 * math.sqrt(3.0))
    expected = side * side
    cube = covered_pixels(rows, background, face)
    print("cube front-on: %d pixels covered, %.0f predicted (%dx%d window)" % (cube, expected, width, height))
    if abs(cube - expected) > 0.02 * expected:
        fail("the cube covers %d pixels, the fit predicts %.0f (more than 2%% apart)" % (cube, expected))

    (_, _, rows2), dom2 = shots["step2"]
    if rows2 == rows:
        fail("step 2 looks exactly like step 0: the slider changed nothing")
    smooth = covered_pixels(rows2, background, face)
    print("Catmull-Clark step 2: %d pixels covered" % smooth)
    if not 0.5 * cube < smooth < cube:
        fail("step 2 covers %d pixels, expected fewer than the cube's %d (and more than half)" % (smooth, cube))
    if '<b id="step-label">M_2</b>' not in dom2:
        fail("the page's step label does not say M_2 after step=2")
    print("ok")


if __name__ == "__main__":
    main()
