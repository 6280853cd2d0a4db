"""A modelling session in Python, notebook style (each "# %%" is a cell; run it whole with
`PYTHONPATH=build/python python3 examples/python/modeling.py [OUTPUT_DIR]`).

A cube grows two legs and a handle (extrusions and a tube between two faces), is rounded by Catmull-Clark
subdivision, and is written out with its operation log, which `build/bin/dlfl replay` replays to the same
mesh. With matplotlib installed the result is also drawn to a PNG.
"""

# %% Set-up: the output folder (the first argument, else ./python_example_output).
import pathlib
import sys

import numpy as np

import dlfl

out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "python_example_output")
out.mkdir(parents=True, exist_ok=True)

# %% A cube from NumPy arrays: vertex i is handle i, face i is handle i (counter-clockwise from outside).
positions = np.array([[x, y, z] for z in (-1, 1) for y in (-1, 1) for x in (-1, 1)], dtype=float)
faces = np.array([[0, 2, 3, 1], [4, 5, 7, 6], [0, 1, 5, 4], [2, 6, 7, 3], [0, 4, 6, 2], [1, 3, 7, 5]])
ed = dlfl.Editor(dlfl.Mesh.from_arrays(positions, faces))
mesh = ed.mesh  # live: follows every operation below
print("start:", mesh, "genus", dlfl.info(mesh)["genus"])


def face_towards(direction):
    """The surface face whose normal points most along `direction`."""
    return max(mesh.surface_faces(), key=lambda f: np.dot(mesh.face_normal(f), direction))


# %% Two legs: the bottom face split in two by an edge, each half extruded downwards in two segments.
bottom = face_towards([0, 0, -1])
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
top, front = face_towards([0, 0, 1]), face_towards([0, -1, 0])
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

# %% A picture, when matplotlib is installed: the polygons shaded by their normal's z.
try:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection
except ImportError:
    print("matplotlib is not installed: no picture")
else:
    points, (offsets, indices) = final.to_arrays()
    polygons = [points[indices[offsets[i] : offsets[i + 1]]] for i in range(len(offsets) - 1)]
    shade = [0.5 + 0.5 * final.face_normal(f)[2] for f in final.surface_faces()]
    figure = plt.figure(figsize=(6, 6))
    axes = figure.add_subplot(projection="3d")
    axes.add_collection3d(Poly3DCollection(polygons, facecolors=plt.cm.viridis(shade), edgecolor="k", linewidth=0.1))
    low, high = points.min(axis=0), points.max(axis=0)
    axes.set_xlim(low[0], high[0]), axes.set_ylim(low[1], high[1]), axes.set_zlim(low[2], high[2])
    axes.set_box_aspect(high - low)
    axes.view_init(elev=15, azim=-30)
    figure.savefig(out / "creature.png", dpi=120)
    print("drew", out / "creature.png")
