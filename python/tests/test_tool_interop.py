"""The binding and the dlfl tool agree: logs written on one side replay on the other to the same hash; info,
the scheme listing and the operation listing are the same documents; and dlfl.render writes the same files
as `dlfl render`."""

import json
import subprocess

import dlfl


def run(tool, *args):
    done = subprocess.run([tool, *map(str, args)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_a_python_log_replays_in_the_tool_to_the_same_hash(tool, data, tmp_path):
    ed = dlfl.Editor(dlfl.read_mesh(data / "dodecahedron.obj"))
    ed.connect_faces(face1=0, face2=6, segments=3)
    with ed.group("bumps"):
        ed.extrude_face(faces=[1, 2], distance=0.3)
        ed.extrude_face(face=3, style="stellate")
    ed.undo()
    ed.insert_edge(0, 2)
    ed.subdivide("honeycomb", t=0.4)
    log, out = tmp_path / "python.log.json", tmp_path / "replayed.json"
    ed.write_log(log)
    run(tool, "replay", log, "-o", out)  # the tool checks the log's final hash itself
    assert json.loads(run(tool, "info", out))["hash"] == ed.mesh.hash()
    assert dlfl.read_mesh(out) == ed.mesh  # the native format keeps every handle


def test_a_tool_log_replays_in_python_to_the_same_hash(tool, data, tmp_path):
    log, out = tmp_path / "tool.log.json", tmp_path / "edited.json"
    run(tool, "edit", data / "cube.obj", "-o", out, "--log", log, "--self-contained",
        "--op", "insert_edge corner1=0 corner2=2",
        "--op", "connect_faces face1=1 face2=3 segments=2",
        "--op", "subdivide scheme=catmull-clark")
    tool_hash = json.loads(run(tool, "info", out))["hash"]
    ed = dlfl.replay(log)
    assert ed.mesh.hash() == tool_hash == dlfl.read_mesh(out).hash()
    assert [op["op"] for op in ed.log()["ops"]][1:] == ["insert_edge", "connect_faces", "subdivide"]


def test_info_is_the_tools_info(tool, data, tmp_path):
    for name in ("cube.obj", "dodecahedron.obj", "tetrahedron.off"):
        mesh = dlfl.read_mesh(data / name)
        assert dlfl.info(mesh) == json.loads(run(tool, "info", data / name))
        assert dlfl.info(mesh, angles=True) == json.loads(run(tool, "info", "--angles", data / name))
    complex = dlfl.CellComplex.from_arrays([[0, 0, 0], [1, 0, 0], [1, 2, 0], [0, 3, 1]], [[0, 1], [1, 2], [2, 3]])
    path = tmp_path / "curve.vtk"
    dlfl.write_cell_complex(complex, path)
    assert dlfl.info(complex) == json.loads(run(tool, "info", path))


def test_the_listings_are_the_tools_listings(tool):
    assert dlfl.schemes() == json.loads(run(tool, "schemes", "--json"))
    assert dlfl.operations() == json.loads(run(tool, "ops", "--json"))


def test_render_writes_the_tools_files(tool, data, tmp_path):
    # Both write through the library's write_png and write_svg, so the same settings give the same bytes;
    # with no settings at all the defaults agree too.
    runs = [
        ([], {}),
        (["--size", "64x48", "--view", "front", "--transparent", "--smooth", "--color-by", "component",
          "--no-edges"],
         {"size": (64, 48), "view": "front", "transparent": True, "smooth": True, "color_by": "component",
          "edges": False}),
        (["--size", "50x70", "--azimuth", "30", "--elevation", "-20", "--zoom", "1.5", "--background", "#203040"],
         {"size": (50, 70), "azimuth": 30, "elevation": -20, "zoom": 1.5, "background": "#203040"}),
    ]
    for k, (flags, settings) in enumerate(runs):
        for ext in ("png", "svg"):
            tool_out, python_out = tmp_path / f"tool{k}.{ext}", tmp_path / f"python{k}.{ext}"
            run(tool, "render", data / "dodecahedron.obj", "-o", tool_out, *flags)
            dlfl.render(dlfl.read_mesh(data / "dodecahedron.obj"), python_out, **settings)
            assert python_out.read_bytes() == tool_out.read_bytes(), (flags, ext)
    # A cell complex likewise.
    complex = dlfl.CellComplex.from_arrays([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0.5], [2, 1, 0]],
                                           [[0, 1, 2, 3], [3, 4]])
    path = tmp_path / "complex.vtk"
    dlfl.write_cell_complex(complex, path)
    run(tool, "render", path, "-o", tmp_path / "tool_complex.png", "--size", "40x30")
    dlfl.render(complex, tmp_path / "python_complex.png", size=(40, 30))
    assert (tmp_path / "python_complex.png").read_bytes() == (tmp_path / "tool_complex.png").read_bytes()
