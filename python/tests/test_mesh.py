"""dlfl.Mesh: construction from arrays in its three forms, NumPy views, counts in closed form, genus,
navigation, geometry, attributes, validate, info and hash."""

import numpy as np
import pytest
from meshes import CUBE_FACES, CUBE_POSITIONS, grid_arrays, torus_arrays

import dlfl


def euler(mesh):
    return mesh.num_vertices - mesh.num_edges + mesh.num_faces


def test_the_three_forms_of_faces_build_the_same_mesh():
    as_lists = dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES)
    as_array = dlfl.Mesh.from_arrays(np.array(CUBE_POSITIONS, dtype=float), np.array(CUBE_FACES, dtype=np.int32))
    offsets = np.arange(0, 25, 4)
    as_flat = dlfl.Mesh.from_arrays(CUBE_POSITIONS, (offsets, np.concatenate(CUBE_FACES)))
    assert (as_lists.num_vertices, as_lists.num_edges, as_lists.num_faces) == (8, 12, 6)
    assert as_lists == as_array == as_flat
    assert as_lists.hash() == as_array.hash() == as_flat.hash()


def test_mixed_polygons_from_offsets_and_indices():
    # A square pyramid: one quad and four triangles, V = 5, E = 8, F = 5.
    positions = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0.5, 1]]
    faces = [[0, 3, 2, 1], [0, 1, 4], [1, 2, 4], [2, 3, 4], [3, 0, 4]]
    offsets = np.cumsum([0] + [len(f) for f in faces])
    mesh = dlfl.Mesh.from_arrays(positions, (offsets, np.concatenate(faces)))
    assert (mesh.num_vertices, mesh.num_edges, mesh.num_faces) == (5, 8, 5)
    assert dlfl.Mesh.from_arrays(positions, faces) == mesh
    assert sorted(mesh.face_size(f) for f in mesh.faces()) == [3, 3, 3, 3, 4]


def test_a_torus_built_from_numpy_arrays_has_genus_one():
    positions, faces = torus_arrays(12, 8)
    mesh = dlfl.Mesh.from_arrays(positions, faces)
    assert (mesh.num_vertices, mesh.num_edges, mesh.num_faces) == (96, 192, 96)
    report = dlfl.validate(mesh)
    assert report["valid"] and report["violation_count"] == 0
    assert [c["genus"] for c in report["components"]] == [1]
    assert report["components"][0]["euler_characteristic"] == 0
    assert dlfl.info(mesh)["genus"] == [1]


def test_positions_round_trip_bit_for_bit_and_are_a_read_only_view(tmp_path):
    rng = np.random.default_rng(7)
    positions, faces = torus_arrays(6, 5)
    positions = positions + rng.normal(scale=1e-3, size=positions.shape)  # full-precision doubles
    positions[0, 0] = -0.0
    positions[1, 1] = 5e-324  # the smallest subnormal
    mesh = dlfl.Mesh.from_arrays(positions, faces)
    view = mesh.positions
    assert view.dtype == np.float64 and view.shape == (30, 3)
    assert view.tobytes() == np.ascontiguousarray(positions).tobytes()  # bit for bit, -0.0 included
    assert not view.flags.writeable
    with pytest.raises(ValueError):
        view[0, 0] = 1.0
    # No copy: every read views the same storage, which lives as long as the array does.
    assert np.shares_memory(view, mesh.positions)
    del mesh
    assert view.tobytes() == np.ascontiguousarray(positions).tobytes()
    # And back through the library: files that keep doubles, an editor's live mesh, the polygon arrays.
    again = dlfl.Mesh.from_arrays(view, faces)
    for name in ("mesh.json", "mesh.ply"):
        dlfl.write_mesh(again, tmp_path / name)
        assert dlfl.read_mesh(tmp_path / name).positions.tobytes() == view.tobytes()
    assert dlfl.Editor(again).mesh.positions.tobytes() == view.tobytes()
    assert again.to_arrays()[0].tobytes() == view.tobytes()


def test_faces_arrays_and_to_arrays_give_back_the_polygons():
    mesh = dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES)
    assert mesh.faces_offsets.tolist() == [0, 4, 8, 12, 16, 20, 24]
    assert mesh.faces_indices.tolist() == sum(CUBE_FACES, [])
    positions, (offsets, indices) = mesh.to_arrays()
    assert positions.tolist() == CUBE_POSITIONS
    assert offsets.tolist() == mesh.faces_offsets.tolist() and indices.tolist() == mesh.faces_indices.tolist()
    assert dlfl.Mesh.from_arrays(*mesh.to_arrays()) == mesh


def test_an_open_grid_gets_one_hole_face_and_its_polygons_leave_it_out():
    positions, faces = grid_arrays(3, 2)
    mesh = dlfl.Mesh.from_arrays(positions, faces)
    # V = 12, E = 3*3 + 4*2 = 17 (horizontal and vertical), F = 6 quads + 1 hole.
    assert (mesh.num_vertices, mesh.num_edges, mesh.num_faces, mesh.num_hole_faces) == (12, 17, 7, 1)
    assert mesh.num_surface_faces == 6
    hole = [f for f in mesh.faces() if mesh.is_hole(f)]
    assert hole == [6] and mesh.face_size(6) == 10  # the boundary: 2 * (3 + 2) edges
    assert len(mesh.faces_offsets) == 7 and mesh.faces_indices.tolist() == faces.ravel().tolist()
    assert dlfl.info(mesh)["holes"] == 1
    boundary = [v for v in mesh.vertices() if mesh.is_boundary_vertex(v)]
    assert len(boundary) == 10  # every vertex but the two inner ones
    assert sum(mesh.is_boundary_edge(e) for e in mesh.edges()) == 10


def test_navigation_on_the_cube():
    mesh = dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES)
    # The corner of the j-th vertex of face i is 4i + j.
    assert mesh.corners(2).tolist() == [8, 9, 10, 11]
    assert [mesh.vertex(c) for c in mesh.corners(2)] == CUBE_FACES[2]
    assert mesh.face_vertices(2).tolist() == CUBE_FACES[2]
    for c in mesh.corners():
        assert mesh.next(mesh.prev(c)) == c
        assert mesh.next(mesh.next(mesh.next(mesh.next(c)))) == c  # quads
        assert mesh.opposite(mesh.opposite(c)) == c
        assert mesh.vertex(mesh.opposite(c)) == mesh.vertex(mesh.next(c))
        assert mesh.prev_around_vertex(mesh.next_around_vertex(c)) == c
        e = mesh.edge(c)
        assert c in (mesh.edge_corner(e, 0), mesh.edge_corner(e, 1))
    for v in mesh.vertices():
        assert mesh.valence(v) == 3 and not mesh.is_point_sphere(v)
        assert len(mesh.vertex_corners(v)) == len(mesh.vertex_faces(v)) == 3
        assert all(mesh.vertex(c) == v for c in mesh.vertex_corners(v))
        neighbours = mesh.vertex_neighbours(v)
        # On the cube [-1, 1]^3 the neighbours of a vertex differ from it in exactly one coordinate.
        p = np.array(mesh.position(v))
        assert all(np.count_nonzero(np.array(mesh.position(w)) != p) == 1 for w in neighbours)
        assert [mesh.find_edge(v, w) for w in neighbours] == mesh.vertex_edges(v).tolist()
    for f in mesh.faces():
        assert mesh.face_size(f) == 4 and not mesh.is_hole(f)
        assert len(set(mesh.face_neighbours(f).tolist())) == 4  # every other face but the opposite one
        assert f not in mesh.face_neighbours(f)
        for e in mesh.face_edges(f):
            assert f in (mesh.edge_face(e, 0), mesh.edge_face(e, 1))
        assert mesh.corner_in_face(mesh.face_vertices(f)[1], f) == mesh.corners(f)[1]
    assert mesh.find_edge(0, 7) is None  # opposite corners of the cube
    assert mesh.corner_in_face(7, 0) is None  # face 0 is z = -1, vertex 7 at z = 1
    u, w = mesh.edge_vertices(0)
    assert mesh.find_edge(u, w) == 0


def test_geometry_of_the_cube():
    mesh = dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES)
    for f in mesh.faces():
        centroid = np.array(mesh.face_centroid(f))
        normal = np.array(mesh.face_normal(f))
        assert mesh.face_area(f) == pytest.approx(4.0)  # a 2 x 2 square
        assert np.count_nonzero(centroid) == 1 and np.abs(centroid).max() == 1.0  # the middle of a side
        np.testing.assert_allclose(normal, centroid)  # outward: the unit normal is the side's direction
    for v in mesh.vertices():
        p = np.array(mesh.position(v))
        np.testing.assert_allclose(mesh.vertex_normal(v), p / np.sqrt(3))


def test_handles_are_checked():
    mesh = dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES)
    for call in (
        lambda: mesh.next(24),
        lambda: mesh.next(-1),
        lambda: mesh.position(8),
        lambda: mesh.face_size(6),
        lambda: mesh.edge_vertices(12),
        lambda: mesh.corners(99),
    ):
        with pytest.raises(dlfl.InvalidArgument, match="is not a live"):
            call()
    with pytest.raises(dlfl.InvalidArgument, match="side must be 0 or 1"):
        mesh.edge_face(0, 2)
    with pytest.raises(dlfl.InvalidArgument, match="element kind"):
        mesh.capacity("cell")
    assert mesh.is_alive("corner", 23) and not mesh.is_alive("corner", 24) and not mesh.is_alive("face", -3)
    assert [mesh.capacity(k) for k in ("vertex", "edge", "face", "corner")] == [8, 12, 6, 24]


def test_point_spheres_and_unused_vertices():
    # A triangle with one vertex that no face uses: the extra vertex is a point sphere with a face of its own.
    positions = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [5, 5, 5]]
    mesh = dlfl.Mesh.from_arrays(positions, [[0, 1, 2]])
    # The triangle (front), its hole (back) and the point sphere's face.
    assert (mesh.num_vertices, mesh.num_edges, mesh.num_faces, mesh.num_hole_faces) == (4, 3, 3, 1)
    assert mesh.is_point_sphere(3) and mesh.valence(3) == 0
    c = mesh.corner(3)
    assert mesh.edge(c) is None and mesh.next_around_vertex(c) == c
    with pytest.raises(dlfl.InvalidArgument, match="point sphere"):
        mesh.opposite(c)
    assert mesh.faces_offsets.tolist() == [0, 3]  # the polygons leave out the hole and the point sphere
    assert dlfl.info(mesh)["point_spheres"] == 1


def test_attributes_written_by_the_editor_read_as_arrays():
    ed = dlfl.Editor(dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES))
    ed.set_attribute(element="face", name="material", index=2, value=7, type="integer")
    ed.set_attribute(element="vertex", name="weight", index=5, value=0.25)
    ed.set_attribute(element="vertex", name="offset", index=1, value=[1, 2, 3])
    ed.set_attribute(element="edge", name="crease", index=3, value=1, type="boolean")
    mesh = ed.mesh
    kinds = [(a["kind"], a["name"], a["type"]) for a in mesh.attributes()]
    assert kinds == [
        ("vertex", "offset", "point"),
        ("vertex", "weight", "number"),
        ("edge", "crease", "boolean"),
        ("face", "material", "integer"),
    ]
    material = mesh.attribute("face", "material")
    assert material.dtype == np.int32 and material.tolist() == [0, 0, 7, 0, 0, 0]
    weight = mesh.attribute("vertex", "weight")
    assert weight.dtype == np.float64 and weight[5] == 0.25 and np.count_nonzero(weight) == 1
    offset = mesh.attribute("vertex", "offset")
    assert offset.shape == (8, 3) and offset[1].tolist() == [1, 2, 3] and not offset[0].any()
    crease = mesh.attribute("edge", "crease")
    assert crease.dtype == np.bool_ and crease.tolist() == [False] * 3 + [True] + [False] * 8
    with pytest.raises(dlfl.InvalidArgument, match="no attribute 'colour'"):
        mesh.attribute("face", "colour")


def test_validate_info_and_hash_agree_on_a_subdivided_mesh(data):
    mesh = dlfl.read_mesh(data / "dodecahedron.obj")
    fine = dlfl.subdivide(mesh, "honeycomb", iterations=1)
    info = dlfl.info(fine)
    # Honeycomb: V' = 2E, E' = 3E, F' = F + V.
    assert (info["vertices"], info["edges"], info["faces"]) == (60, 90, 32)
    assert info["face_sizes"] == {"5": 12, "6": 20} and info["valences"] == {"3": 60}
    assert info["hash"] == fine.hash() and info["valid"] and info["genus"] == [0]
    assert info["euler_characteristic"] == 2
    assert "angles" not in info and "angles" in dlfl.info(fine, angles=True)
    assert fine.hash() != mesh.hash() and len(fine.hash()) == 32


def test_copies_and_compaction():
    mesh = dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES)
    ed = dlfl.Editor(mesh)
    ed.delete_edge(0)  # faces merge: a tombstone face and edge remain
    live = ed.mesh
    assert live.live and not mesh.live
    kept = live.copy()
    assert not kept.live and kept == live
    assert (kept.num_edges, kept.capacity("edge")) == (11, 12)
    dense = kept.compacted()
    assert (dense.num_edges, dense.capacity("edge"), dense.num_faces, dense.capacity("face")) == (11, 11, 5, 5)
    assert dlfl.validate(dense)["valid"]
    ed.undo()
    assert live == mesh and kept != mesh  # the live mesh follows the editor, the copy does not
    # Arrays of a live mesh are copies: its storage moves with the editor's operations.
    assert not np.shares_memory(live.positions, live.positions)


def test_bad_polygon_lists_raise_polygon_errors_naming_the_face():
    with pytest.raises(dlfl.PolygonError) as e:
        dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES + [[0, 1, 2]])  # edge 0-1 used twice one way
    assert e.value.element == "face" and e.value.index == 6
    with pytest.raises(dlfl.PolygonError) as e:
        dlfl.Mesh.from_arrays(CUBE_POSITIONS, [[0, 2, 3, 1], [4, 5, -7, 6]])
    assert e.value.element == "face" and e.value.index == 1 and "negative" in str(e.value)
    with pytest.raises(dlfl.PolygonError) as e:
        dlfl.Mesh.from_arrays([[0, 0, 0], [1, 0, np.nan], [0, 1, 0]], [[0, 1, 2]])
    assert e.value.element == "vertex" and e.value.index == 1
    with pytest.raises(dlfl.InvalidArgument, match="offsets decrease"):
        dlfl.Mesh.from_arrays(CUBE_POSITIONS, ([0, 8, 4, 24], list(range(24))))
    with pytest.raises(dlfl.InvalidArgument, match=r"\(n, 3\)"):
        dlfl.Mesh.from_arrays([[0, 0], [1, 0]], [[0, 1]])
    with pytest.raises(dlfl.InvalidArgument, match="integers"):
        dlfl.Mesh.from_arrays(CUBE_POSITIONS, np.array(CUBE_FACES, dtype=float))
