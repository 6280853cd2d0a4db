"""dlfl.Editor: every registered operation as a method, apply by name, undo and redo exactly, groups, the
log and its replay."""

import inspect
import keyword

import numpy as np
import pytest
from meshes import CUBE_FACES, CUBE_POSITIONS

import dlfl


def cube():
    return dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES)


def counts(mesh):
    return mesh.num_vertices, mesh.num_edges, mesh.num_faces


def test_every_registered_operation_is_a_method_with_its_declared_defaults():
    ops = dlfl.operations()
    names = [op["name"] for op in ops]
    assert names == sorted(names) and len(names) == len(set(names)) and "insert_edge" in names
    for op in ops:
        method = getattr(dlfl.Editor, op["name"])
        if op["name"] == "mesh":  # the current mesh, a property; the operation is set_mesh or apply("mesh")
            assert isinstance(method, property)
            continue
        assert callable(method)
        if inspect.isfunction(method):  # generated (mesh, subdivide, undo and redo are the editor's own)
            assert op["doc"][1:] in method.__doc__
            parameters = list(inspect.signature(method).parameters.values())[1:]
            for p, declared in zip(parameters, op["params"]):
                assert p.name.rstrip("_") == declared["name"]
                assert keyword.iskeyword(declared["name"]) == p.name.endswith("_")
                if declared["default"] is not None:
                    assert p.default == declared["default"]
                elif not declared["optional"]:
                    assert p.default is inspect.Parameter.empty
            assert len(parameters) == len(op["params"])
    own = {"mesh", "subdivide", "undo", "redo"}
    assert all(inspect.isfunction(getattr(dlfl.Editor, n)) for n in names if n not in own)


def test_insert_edge_splits_a_face_and_undo_restores_it_exactly():
    ed = dlfl.Editor(cube())
    before, before_hash = ed.mesh.copy(), ed.mesh.hash()
    out = ed.insert_edge(0, 2)  # corners 0 and 2 of face 0: its diagonal
    assert counts(ed.mesh) == (8, 13, 7)
    assert set(out) == {"edge", "created_face"} and out["edge"] == 12 and out["created_face"] == 6
    assert ed.mesh.face_size(0) == 3 and ed.mesh.face_size(6) == 3
    assert ed.undo() is True
    assert ed.mesh == before and ed.mesh.hash() == before_hash
    assert ed.redo() is True and counts(ed.mesh) == (8, 13, 7)
    assert ed.redo() is False  # nothing left to redo


def test_keywords_positionals_and_apply_by_name_agree():
    a, b, c = dlfl.Editor(cube()), dlfl.Editor(cube()), dlfl.Editor(cube())
    a.connect_faces(face1=0, face2=1, segments=4)
    b.connect_faces(0, 1, segments=4)
    c.apply("connect_faces", 0, 1, segments=4)
    # connect_faces: V+m(s-1), E+ms+m(s-1), F-2+ms with m = 4, s = 4; the genus goes from 0 to 1.
    assert counts(a.mesh) == (8 + 12, 12 + 16 + 12, 6 - 2 + 16)
    assert dlfl.info(a.mesh)["genus"] == [1]
    assert a.mesh == b.mesh == c.mesh


def test_extrusions_follow_their_closed_forms():
    ed = dlfl.Editor(cube())
    ed.extrude_face(face=1, distance=0.5)  # cubical, n = 4, s = 1: V+4, E+8, F+4
    assert counts(ed.mesh) == (12, 20, 10)
    ed.extrude_face(faces=[2, 3], distance=0.5, segments=2)  # two quads, s = 2: V+16, E+32, F+16
    assert counts(ed.mesh) == (28, 52, 26)
    ed.extrude_face(face=0, style="stellate")  # V+1, E+n, F+n-1
    assert counts(ed.mesh) == (29, 56, 29)
    assert dlfl.validate(ed.mesh)["components"][0]["genus"] == 0


def test_subdivide_in_the_editor_is_one_entry():
    ed = dlfl.Editor(cube())
    ed.subdivide("catmull-clark", iterations=2)
    # Catmull-Clark on a closed quad mesh: V' = V + E + F, E' = 4E, F' = 4F (all quads).
    assert counts(ed.mesh) == (98, 192, 96)
    assert [e["label"] for e in ed.undo_history()] == ["mesh", "subdivide"]
    ed.undo()
    assert ed.mesh == cube()
    with pytest.raises(dlfl.ParameterError) as e:
        ed.subdivide("honeycomb", t=2)
    assert e.value.parameter == "params.t" and "outside [0, 1]" in str(e.value)
    assert ed.mesh == cube() and [e["label"] for e in ed.undo_history()] == ["mesh"]


def test_a_group_is_one_entry_and_undo_inside_it_is_refused():
    ed = dlfl.Editor(cube())
    start = ed.mesh.copy()
    with ed.group("two diagonals") as same:
        assert same is ed and ed.group_depth == 1
        ed.insert_edge(0, 2)
        before_undo = ed.mesh.copy()
        with pytest.raises(dlfl.InvalidArgument, match="inside the open group 'two diagonals'"):
            ed.undo()
        assert ed.mesh == before_undo and ed.group_depth == 1  # the refusal changed nothing
        ed.insert_edge(4, 6)
    assert ed.group_depth == 0
    assert ed.undo_history()[-1] == {"label": "two diagonals", "operations": 2}
    assert counts(ed.mesh) == (8, 14, 8)
    ed.undo()  # both diagonals at once
    assert ed.mesh == start


def test_a_group_is_ended_when_its_block_raises():
    ed = dlfl.Editor(cube())
    with pytest.raises(dlfl.InvalidArgument):
        with ed.group("half"):
            ed.insert_edge(0, 2)
            ed.insert_edge(0, 99)  # no corner 99: refused before anything changes
    assert ed.group_depth == 0 and ed.undo_history()[-1] == {"label": "half", "operations": 1}
    ed.undo()
    assert ed.mesh == cube()


def test_errors_leave_the_mesh_the_history_and_the_log_unchanged():
    ed = dlfl.Editor(cube())
    ed.insert_edge(0, 2)
    mesh, log, history = ed.mesh.copy(), ed.log(), ed.undo_history()
    for bad in (
        lambda: ed.insert_edge(0, 1000),
        lambda: ed.insert_edge(corner1=0, corner3=2),
        lambda: ed.insert_edge(0, 2, 5),
        lambda: ed.insert_edge(0, corner1=2),
        lambda: ed.connect_faces(face1=0, face2=0),
        lambda: ed.extrude_face(face=0, faces=[1]),
        lambda: ed.apply("no_such_operation"),
        lambda: ed.set_position(0, "not a point"),
    ):
        with pytest.raises(dlfl.InvalidArgument):
            bad()
    assert ed.mesh == mesh and ed.log() == log and ed.undo_history() == history


def test_a_wrong_keyword_names_the_operation_and_its_known_parameters():
    ed = dlfl.Editor(cube())
    with pytest.raises(dlfl.ParameterError) as e:
        ed.insert_edge(corner1=0, corner3=2)
    assert e.value.parameter == "corner3"
    assert str(e.value) == (
        "insert_edge: unknown parameter 'corner3' (did you mean 'corner1'?; known: corner1, corner2)"
    )
    with pytest.raises(dlfl.ParameterError, match=r"insert_edge: 3 positional arguments for 2 parameters"):
        ed.insert_edge(0, 2, 5)
    with pytest.raises(dlfl.ParameterError, match="parameter corner1 given twice"):
        ed.insert_edge(0, corner1=2)


def test_keyword_named_parameters_take_a_trailing_underscore():
    a, b = dlfl.Editor(cube()), dlfl.Editor(cube())
    a.smooth(lambda_=0.25)
    b.apply("smooth", **{"lambda": 0.25})
    assert a.mesh == b.mesh and a.mesh != cube()
    assert a.log()["ops"][-1]["lambda"] == 0.25


def test_handles_and_lists_may_be_numpy_values():
    a, b = dlfl.Editor(cube()), dlfl.Editor(cube())
    corners = a.mesh.corners(0)  # uint32
    a.insert_edge(corners[0], corners[2])
    b.insert_edge(0, 2)
    assert a.mesh == b.mesh
    a.extrude_face(faces=np.array([1, 2]), direction=np.array([0.0, 0.0, 1.0]))
    b.extrude_face(faces=[1, 2], direction=(0, 0, 1))
    assert a.mesh == b.mesh


def test_the_live_mesh_follows_and_positions_move_with_set_position():
    ed = dlfl.Editor(cube())
    live = ed.mesh
    ed.set_position(3, [0.5, 0.25, 0.125])
    assert live.position(3) == (0.5, 0.25, 0.125)
    assert live.positions[3].tolist() == [0.5, 0.25, 0.125]
    out = ed.create_vertex(position=[9, 9, 9])
    assert out == {"vertex": 8} and live.is_point_sphere(8)


def test_the_log_replays_to_the_same_mesh(tmp_path):
    ed = dlfl.Editor(cube())
    ed.insert_edge(0, 2)
    with ed.group("handle"):
        ed.connect_faces(face1=1, face2=3, segments=2)
    ed.undo()
    ed.redo()
    ed.subdivide("doo-sabin")
    log = ed.log()
    assert log["format"] == "dlfl-oplog" and log["final_hash"] == ed.mesh.hash()
    ops = [op["op"] for op in log["ops"]]
    assert ops == ["mesh", "insert_edge", "begin_group", "connect_faces", "end_group", "undo", "redo", "subdivide"]
    again = dlfl.replay(log)
    assert again.mesh == ed.mesh and again.mesh.hash() == ed.mesh.hash()
    path = tmp_path / "session.json"
    ed.write_log(path)
    assert dlfl.replay(path).mesh == ed.mesh
    assert dlfl.replay(str(path)).log()["final_hash"] == ed.mesh.hash()


def test_an_editor_started_from_a_path_logs_a_load_with_its_hash(data, tmp_path):
    ed = dlfl.Editor(data / "cube.obj")
    first = ed.log()["ops"][0]
    assert first["op"] == "load" and first["hash"] == cube().hash() and first["path"] == str(data / "cube.obj")
    assert "mesh" not in first
    assert "mesh" in dlfl.Editor(data / "cube.obj", embed_meshes=True).log()["ops"][0]
    ed.insert_edge(0, 2)
    assert dlfl.replay(ed.log()).mesh == ed.mesh


def test_undo_limit_keeps_the_latest_entries():
    ed = dlfl.Editor(cube(), undo_limit=2)
    assert ed.undo_limit == 2 and not ed.embed_meshes
    for k in range(4):
        ed.set_position(0, [k, 0, 0])
    assert len(ed.undo_history()) == 2
    assert ed.undo() and ed.undo() and not ed.undo()
    assert ed.mesh.position(0) == (1.0, 0.0, 0.0)
    assert ed.can_redo and not ed.can_undo
