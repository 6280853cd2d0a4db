"""A modelling session in Python, notebook style (each "# %%" is a cell; run it whole with
`PYTHONPATH=build/python python3 examples/python/modeling.py [OUTPUT_DIR]`).

A cube grows two legs and a handle (extrusions and a tube between two faces), is rounded by Catmull-Clark
subdivision, and is written out with its operation log, which `build/bin/dlfl replay` replays to the same
mesh, and drawn with dlfl.render, the library's renderer, to a PNG (nothing else to install).
"""

# %% Set-up: the output folder (the first argument, else ./python_example_output).
import pathlib
import sys

import numpy as np

import dlfl

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "python_example_output")
out.mkdir(parents=True, exist_ok=True)

# %% A cube from NumPy arrays: vertex i is handle i, face i is handle i (counter-clockwise from outside).
# Up is +y and the front +z, as the renderer takes models.
positions = np.array([[x, y, z] for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)], dtype=float)
faces = np.array([[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]])
ed = dlfl.Editor(dlfl.Mesh.from_arrays(positions, faces))
mesh = ed.mesh  # live: follows every operation below
print("start:", mesh, "genus", dlfl.info(mesh)["genus"])


def face_towards(direction):
    """The surface face whose normal points most along `direction`."""
    return max(mesh.surface_faces(), key=lambda f: np.dot(mesh.face_normal(f), direction))


# %% Two legs: the bottom face split in two by an edge, each half extruded downwards in two segments.
bottom = face_towards([0, -1, 0])
corners = mesh.face_corners(bottom)
with ed.group("legs"):
    # A cut from the midpoint of one edge to the midpoint of the opposite edge.
    a = ed.subdivide_edge(edge=mesh.edge(corners[0]))["vertex"]
    b = ed.subdivide_edge(edge=mesh.edge(corners[2]))["vertex"]
    split = ed.insert_edge(mesh.corner_in_face(a, bottom), mesh.corner_in_face(b, bottom))
    for leg in (bottom, split["created_face"]):
        ed.extrude_face(face=leg, distance=1.5, segments=2, scale=0.6)
print("legs:", mesh)

# %% A handle, as on a mug: the top and front faces inset, then joined by a tube of six segments that leaves
# and enters along their normals.
top, front = face_towards([0, 1, 0]), face_towards([0, 0, 1])
ed.inset_face(faces=[top, front], amount=0.4)
ed.connect_faces(face1=top, face2=front, segments=6, curve="hermite", weight1=1.5, weight2=1.5)
info = dlfl.info(mesh)
print("handle:", mesh, "genus", info["genus"])
assert info["genus"] == [1]

# %% Catmull-Clark twice: the topology stays (genus 1), the shape rounds.
ed.subdivide("catmull-clark", iterations=2)
final = ed.mesh.copy()  # a mesh of its own: its arrays are views, no copy
report = dlfl.validate(final)
print("subdivided:", final, "valid", report["valid"], "genus", [c["genus"] for c in report["components"]])
print("positions:", final.positions.shape, final.positions.dtype, "read-only view:", not final.positions.flags.writeable)

# %% Files: the mesh and the session's log (replayable by `dlfl replay`).
dlfl.write_mesh(final, out / "creature.obj")
ed.write_log(out / "creature.log.json")
assert dlfl.replay(out / "creature.log.json").mesh == final
print("wrote", out / "creature.obj", "and", out / "creature.log.json")

# %% Pictures with the library's renderer (what `dlfl render` draws): a PNG file, and a picture as a NumPy
# array of RGBA bytes, (height, width, 4), for a notebook to show (e.g. matplotlib's imshow) or a script to
# inspect; here the share of the picture that the creature covers from the front.
dlfl.render(final, out / "creature.png", size=(800, 600), view="iso", smooth=True)
picture = dlfl.render(final, size=(400, 300), view="front", transparent=True)
covered = np.count_nonzero(picture[..., 3]) / (picture.shape[0] * picture.shape[1])
print("drew", out / "creature.png", f"; from the front the creature covers {covered:.0%} of the picture")
assert 0 < covered < 1
