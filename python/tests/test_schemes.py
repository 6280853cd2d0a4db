"""Schemes by name with keyword parameters, their closed-form counts, the scheme listing, and MLCA on cell
complexes."""

import numpy as np
import pytest
from meshes import CUBE_FACES, CUBE_POSITIONS, prism_rows_arrays

import dlfl


def counts(mesh):
    return mesh.num_vertices, mesh.num_edges, mesh.num_faces


def cube():
    return dlfl.Mesh.from_arrays(CUBE_POSITIONS, CUBE_FACES)


def test_counts_in_closed_form(data):
    dodecahedron = dlfl.read_mesh(data / "dodecahedron.obj")  # V 20, E 30, F 12
    tetrahedron = dlfl.read_mesh(data / "tetrahedron.off")  # V 4, E 6, F 4
    # Honeycomb: V' = 2E, E' = 3E, F' = F + V; twice: (60, 90, 32), then (180, 270, 92).
    assert counts(dlfl.subdivide(dodecahedron, "honeycomb", iterations=2, t=0.5)) == (180, 270, 92)
    # Loop: V' = V + E, E' = 2E + 3F, F' = 4F.
    assert counts(dlfl.subdivide(tetrahedron, "loop")) == (10, 24, 16)
    # sqrt(3): V' = V + F, E' = 3E, F' = 3F.
    assert counts(dlfl.subdivide(tetrahedron, "sqrt3")) == (8, 18, 12)
    # Doo-Sabin: V' = corners, E' = 2 corners, F' = V + E + F.
    assert counts(dlfl.subdivide(cube(), "doo-sabin")) == (24, 48, 26)
    # Dual: V' = F, E' = E, F' = V (the octahedron).
    assert counts(dlfl.subdivide(cube(), "dual")) == (6, 12, 8)
    # Catmull-Clark: V' = V + E + F, E' = 2E + corners, F' = corners; MLCA on quads has its connectivity.
    assert counts(dlfl.subdivide(cube(), "catmull-clark")) == (26, 48, 24)
    assert counts(dlfl.subdivide(cube(), "mlca")) == (26, 48, 24)
    assert counts(dlfl.subdivide(cube(), "catmull-clark", iterations=0)) == (8, 12, 6)


def test_every_registered_scheme_runs_with_its_defaults(data):
    listed = dlfl.schemes()
    assert [s["name"] for s in listed] == sorted(s["name"] for s in listed)
    triangles = dlfl.read_mesh(data / "tetrahedron.off")
    for scheme in listed:
        for p in scheme["params"]:
            assert {"name", "type", "default", "keywords", "doc", "optional"} <= set(p)
        mesh = triangles if scheme["name"] in ("loop", "sqrt3") else cube()
        fine = dlfl.subdivide(mesh, scheme["name"])
        report = dlfl.validate(fine)
        assert report["valid"], scheme["name"]
        assert [c["genus"] for c in report["components"]] == [0], scheme["name"]
        assert fine.num_faces > mesh.num_faces or scheme["name"] == "dual", scheme["name"]


def test_the_function_and_the_editor_run_the_same_scheme():
    mesh = cube()
    ed = dlfl.Editor(mesh)
    ed.subdivide("honeycomb", iterations=2, t=0.3, a=0.5)
    assert ed.mesh == dlfl.subdivide(mesh, "honeycomb", iterations=2, t=0.3, a=0.5)
    assert ed.log()["ops"][-1]["params"]["t"] == 0.3
    assert mesh == cube()  # the input is not changed


def test_point_and_keyword_parameters():
    mesh = cube()
    # Corner pushing moves the old vertices towards the centre.
    by_keyword = dlfl.subdivide(mesh, "mp-pushing", center="centroid")
    by_tuple = dlfl.subdivide(mesh, "mp-pushing", center=(0, 0, 0))  # the cube's centroid
    by_array = dlfl.subdivide(mesh, "mp-pushing", center=np.zeros(3))
    assert by_keyword == by_tuple == by_array
    assert dlfl.subdivide(mesh, "mp-pushing", center=(0.1, 0, 0)) != by_tuple


def test_bad_scheme_parameters_are_refused_before_any_work():
    mesh = cube()
    with pytest.raises(dlfl.ParameterError) as e:
        dlfl.subdivide(mesh, "honeycomb", t=2)
    assert e.value.parameter == "params.t" and "outside [0, 1]" in str(e.value)
    with pytest.raises(dlfl.ParameterError) as e:
        dlfl.subdivide(mesh, "honeycomb", tension=0.5)
    assert e.value.parameter == "params.tension" and "unknown parameter 'tension'" in str(e.value)
    with pytest.raises(dlfl.ParameterError) as e:
        dlfl.subdivide(mesh, "catmull-clark", iterations=65)
    assert e.value.parameter == "iterations"
    with pytest.raises(dlfl.TopologyError):
        dlfl.subdivide(mesh, "loop")  # quads: Loop takes triangles only


def square_curve():
    # A closed square of four segments.
    return dlfl.CellComplex.from_arrays([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], [[0, 1], [1, 2], [2, 3], [3, 0]])


def test_mlca_on_a_closed_curve_is_cubic_b_spline_subdivision():
    fine = dlfl.mlca_subdivide(square_curve())
    assert (fine.num_vertices, fine.num_cells) == (8, 8)
    assert fine.dimensions().tolist() == [1] * 8
    # Input vertex i stays vertex i, moved to (p[i-1] + 6 p[i] + p[i+1]) / 8.
    np.testing.assert_allclose(fine.positions[:4], [[1 / 8, 1 / 8, 0], [7 / 8, 1 / 8, 0], [7 / 8, 7 / 8, 0], [1 / 8, 7 / 8, 0]])
    # The new vertices are the midpoints of the segments.
    assert sorted(map(tuple, fine.positions[4:].tolist())) == [(0, 0.5, 0), (0.5, 0, 0), (0.5, 1, 0), (1, 0.5, 0)]
    assert counts_of(dlfl.mlca_subdivide(square_curve(), iterations=3)) == (32, 32)


def counts_of(complex):
    return complex.num_vertices, complex.num_cells


def test_mlca_on_a_hexahedron_and_a_quad():
    corners = [[x, y, z] for z in (0, 1) for y in (0, 1) for x in (0, 1)]  # tensor-product order
    hexahedron = dlfl.CellComplex.from_arrays(corners, [list(range(8))])
    fine = dlfl.mlca_subdivide(hexahedron)
    assert counts_of(fine) == (27, 8) and fine.dimensions().tolist() == [3] * 8
    quad = dlfl.CellComplex.from_arrays(corners[:4], np.array([[0, 1, 2, 3]]))
    assert counts_of(dlfl.mlca_subdivide(quad, iterations=2)) == (25, 16)


def test_cell_complex_arrays_are_views_and_files_round_trip(tmp_path):
    curve = square_curve()
    assert not curve.positions.flags.writeable and np.shares_memory(curve.positions, curve.positions)
    assert curve.offsets.tolist() == [0, 2, 4, 6, 8] and curve.indices.tolist() == [0, 1, 1, 2, 2, 3, 3, 0]
    for name, ascii in (("curve.vtk", False), ("curve_ascii.vtk", True), ("curve.obj", False)):
        dlfl.write_cell_complex(curve, tmp_path / name, ascii=ascii)
        back = dlfl.read_cell_complex(tmp_path / name)
        assert back.positions.tolist() == curve.positions.tolist()
        assert back.indices.tolist() == curve.indices.tolist()
    info = dlfl.info(curve)
    assert info["cells_by_dimension"] == {"0": 0, "1": 4, "2": 0, "3": 0}
    assert info["bbox"] == [[0, 0, 0], [1, 1, 0]]


def test_bad_cell_complexes_are_refused():
    with pytest.raises(dlfl.InvalidArgument, match="cell 1"):
        dlfl.CellComplex.from_arrays([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1], [1, 2, 0]])  # three vertices
    with pytest.raises(dlfl.InvalidArgument, match="cell 0"):
        dlfl.CellComplex.from_arrays([[0, 0, 0], [1, 0, 0]], [[0, 5]])
    with pytest.raises(dlfl.InvalidArgument):
        dlfl.info(square_curve(), angles=True)


def test_the_lateral_fixes_planarize_and_hexagonalize():
    # The hexagonal prism with 2 rows of quads per side is convex, so every concave edge is an artifact; the
    # planarize rule of docs/lateral_artifacts.md removes them all, keeping the honeycomb's counts
    # (V' = 2E, E' = 3E, F' = F + V: V 18, E 30, F 14 -> 60, 90, 32 -> 180, 270, 92).
    prism = dlfl.Mesh.from_arrays(*prism_rows_arrays(6, 2))
    assert counts(prism) == (18, 30, 14)
    fixed = dlfl.subdivide(prism, "honeycomb", iterations=2, planarize=1)
    assert counts(fixed) == (180, 270, 92)
    assert dlfl.info(fixed, shape=True)["concave_edges"] == 0
    assert "concave_edges" not in dlfl.info(fixed)
    ed = dlfl.Editor(prism)
    ed.subdivide("honeycomb", iterations=2, planarize=1)
    assert ed.mesh == fixed and ed.log()["ops"][-1]["params"]["planarize"] == 1
    # hexagonalize, a method of the editor like every registered operation: on the 6-gonal prism with 3 rows
    # its closed form gives V 24 -> 156, E 42 -> 234, F 20 -> 80 (docs/modeling.md); undone, the prism again.
    prism3 = dlfl.Mesh.from_arrays(*prism_rows_arrays(6, 3))
    ed = dlfl.Editor(prism3)
    ed.hexagonalize(angle=1.0)
    assert counts(ed.mesh) == (156, 234, 80)
    assert dlfl.info(ed.mesh, shape=True)["concave_edges"] == 0
    ed.undo()
    assert ed.mesh == prism3
    with pytest.raises(dlfl.ParameterError):
        ed.hexagonalize(angle=200.0)
