"""The exceptions mirror the C++ hierarchy, each raised by the library with its fields and its message."""

import json

import pytest
from meshes import CUBE_FACES, CUBE_POSITIONS

import dlfl


def test_the_hierarchy_is_the_libraries():
    assert issubclass(dlfl.InvalidArgument, dlfl.Error) and issubclass(dlfl.InvalidArgument, ValueError)
    assert issubclass(dlfl.ParameterError, dlfl.InvalidArgument)
    assert issubclass(dlfl.UnknownNameError, dlfl.InvalidArgument)
    assert issubclass(dlfl.TopologyError, dlfl.Error) and not issubclass(dlfl.TopologyError, ValueError)
    assert issubclass(dlfl.PolygonError, dlfl.TopologyError)
    assert issubclass(dlfl.IoError, dlfl.Error) and issubclass(dlfl.LogError, dlfl.IoError)
    assert dlfl.Error.__module__ == "dlfl" and repr(dlfl.LogError("x")) == "LogError('x')"


def test_invalid_argument():
    mesh = dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES)
    with pytest.raises(dlfl.InvalidArgument) as e:
        mesh.vertex(24)
    assert type(e.value) is dlfl.InvalidArgument and str(e.value) == "vertex: 24 is not a live corner of this mesh"


def test_parameter_error_names_the_parameter():
    mesh = dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES)
    with pytest.raises(dlfl.ParameterError) as e:
        dlfl.subdivide(mesh, "honeycomb", a=1.5)
    assert e.value.parameter == "params.a" and str(e.value).startswith("honeycomb: parameter a = 1.5")
    with pytest.raises(dlfl.ParameterError) as e:
        dlfl.Editor(mesh).extrude_face(face=0, segments=0)
    assert e.value.parameter == "segments" and "extrude_face: parameter segments" in str(e.value)


def test_unknown_name_error_suggests_a_name():
    with pytest.raises(dlfl.UnknownNameError) as e:
        dlfl.Editor().apply("insert_edg")
    assert e.value.suggestion == "insert_edge" and "did you mean 'insert_edge'?" in str(e.value)
    with pytest.raises(dlfl.UnknownNameError) as e:
        dlfl.subdivide(dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES), "catmul-clark")
    assert e.value.suggestion == "catmull-clark"
    with pytest.raises(dlfl.UnknownNameError) as e:
        dlfl.Editor().apply("zzzzzzzzzzzz")
    assert e.value.suggestion is None


def test_topology_error():
    # Two triangles on one edge: a 2-gon-free polygon file cannot hold the double edge an edit makes.
    ed = dlfl.Editor(dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES))
    ed.insert_edge(0, 1)  # corners 0 and 1 of face 0 are neighbours: a second edge between their vertices
    with pytest.raises(dlfl.TopologyError) as e:
        dlfl.write_mesh(ed.mesh, "never-written.obj")
    assert type(e.value) is dlfl.TopologyError
    with pytest.raises(dlfl.TopologyError):
        ed.mesh.to_arrays()


def test_polygon_error_names_the_element():
    with pytest.raises(dlfl.PolygonError) as e:
        dlfl.Mesh.from_arrays(CUBE_POSITIONS, [[0, 2, 3, 1], [0, 1]])
    assert (e.value.element, e.value.index) == ("face", 1)
    assert str(e.value) == "face 1: has 2 vertices; at least 3 are needed"
    # Two triangles sharing only vertex 0: a non-manifold vertex.
    with pytest.raises(dlfl.PolygonError) as e:
        dlfl.Mesh.from_arrays([[0, 0, 0], [1, 0, 0], [1, 1, 0], [-1, 0, 0], [-1, -1, 0]], [[0, 1, 2], [0, 3, 4]])
    assert (e.value.element, e.value.index) == ("vertex", 0)


def test_io_error_has_the_path_and_the_line(tmp_path):
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n")
    with pytest.raises(dlfl.IoError) as e:
        dlfl.read_mesh(bad)
    assert type(e.value) is dlfl.IoError and e.value.path == str(bad) and e.value.line == 3
    with pytest.raises(dlfl.IoError) as e:
        dlfl.read_mesh(tmp_path / "missing.off")
    assert e.value.path == str(tmp_path / "missing.off") and e.value.line is None
    with pytest.raises(dlfl.IoError) as e:
        dlfl.write_mesh(dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES), tmp_path / "cube.fbx")
    assert e.value.path == str(tmp_path / "cube.fbx")


def test_log_error_has_the_op_index_and_the_field(tmp_path):
    ed = dlfl.Editor(dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES))
    ed.insert_edge(0, 2)
    ed.subdivide("honeycomb")
    log = ed.log()
    log["ops"][1]["corner2"] = 99  # no such corner at that point
    with pytest.raises(dlfl.LogError) as e:
        dlfl.replay(log)
    assert (e.value.op_index, e.value.field) == (1, "corner2") and e.value.path == "<dict>"
    log = ed.log()
    log["ops"][2]["params"]["t"] = 3
    path = tmp_path / "bad.log.json"
    path.write_text(json.dumps(log))
    with pytest.raises(dlfl.LogError) as e:
        dlfl.replay(path)
    assert (e.value.op_index, e.value.field) == (2, "params.t") and e.value.path == str(path)
    path.write_text('{"format": "dlfl-oplog", "version": 99, "ops": []}')
    with pytest.raises(dlfl.LogError) as e:
        dlfl.replay(path)
    assert e.value.op_index is None and e.value.field == "version"
    log = ed.log()
    log["final_hash"] = "0" * 32
    with pytest.raises(dlfl.LogError) as e:
        dlfl.replay(log)
    assert e.value.field == "final_hash"
    assert dlfl.replay(log, verify=False).mesh == ed.mesh


def test_every_error_is_caught_as_dlfl_error():
    for bad in (
        lambda: dlfl.read_mesh("/nonexistent/x.obj"),
        lambda: dlfl.Mesh.from_arrays(CUBE_POSITIONS, [[0, 1]]),
        lambda: dlfl.Editor().apply("nothing"),
        lambda: dlfl.replay({"format": "nope"}),
    ):
        with pytest.raises(dlfl.Error):
            bad()
