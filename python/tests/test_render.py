"""dlfl.render: pictures whose pixels follow from the camera's fit formula (render/camera.h: scale = zoom *
min(0.9 W / extent_right, 0.9 H / extent_up)) and the documented light, arrays of the asked size with row 0
at the top, files by extension, and refusals that name the parameter and write nothing. That the binding's
files are the tool's is checked in test_tool_interop.py."""

import math

import numpy as np
import pytest
from meshes import CUBE_FACES, CUBE_POSITIONS

import dlfl


def unit_cube():
    """The cube [0, 1]^3."""
    return dlfl.Mesh.from_arrays((np.array(CUBE_POSITIONS, dtype=float) + 1) / 2, CUBE_FACES)


def coverage(picture):
    """Covered pixels on a transparent background: the alpha channel summed (partly covered pixels count by
    their share)."""
    return picture[..., 3].sum(dtype=np.int64) / 255


def test_the_array_is_height_by_width_rgba_bytes():
    picture = dlfl.render(unit_cube(), size=(37, 23))
    assert picture.shape == (23, 37, 4)
    assert picture.dtype == np.uint8
    assert picture.flags.c_contiguous and picture.flags.writeable  # the caller's own
    assert dlfl.render(unit_cube(), size=np.array([5, 7])).shape == (7, 5, 4)  # NumPy integers too
    assert dlfl.render(unit_cube()).shape == (600, 800, 4)  # the tool's default 800x600


@pytest.mark.parametrize("width, height, zoom", [(160, 120, 1.0), (90, 200, 1.0), (160, 120, 0.5)])
def test_a_front_view_of_the_unit_cube_covers_its_projected_square(width, height, zoom):
    # From the front the cube is the unit square (extent 1 along right and up), so the fitted scale is
    # zoom * 0.9 * min(W, H) pixels per unit and the square that many pixels wide, centred.
    picture = dlfl.render(unit_cube(), size=(width, height), view="front", zoom=zoom, edges=False,
                          transparent=True)
    side = zoom * 0.9 * min(width, height)
    assert coverage(picture) == pytest.approx(side * side, rel=0.01)
    rows, cols = np.nonzero(picture[..., 3])
    assert cols.min() == math.floor(width / 2 - side / 2) and cols.max() == math.ceil(width / 2 + side / 2) - 1
    assert rows.min() == math.floor(height / 2 - side / 2) and rows.max() == math.ceil(height / 2 + side / 2) - 1


def test_the_front_face_has_the_documented_flat_colour():
    # color_by "none" fills with (201, 211, 224); a face facing the viewer is lit at 0.35 + 0.65 cos, with
    # the light from (-0.3, 0.4, 1) in camera space: cos = 1 / sqrt(1.25) (docs/rendering.md, shading.h).
    intensity = 0.35 + 0.65 / math.sqrt(1.25)
    expected = [round(c * intensity) for c in (201, 211, 224)] + [255]
    picture = dlfl.render(unit_cube(), size=(80, 60), view="front", color_by="none")
    assert picture[30, 40].tolist() == expected
    assert picture[0, 0].tolist() == [255, 255, 255, 255]  # the white background outside the margin


def test_a_transparent_background_has_alpha_0_around_an_opaque_model():
    picture = dlfl.render(unit_cube(), size=(64, 48), transparent=True)
    assert picture[0, 0, 3] == 0 and picture[-1, -1, 3] == 0
    assert picture[24, 32, 3] == 255
    black = dlfl.render(unit_cube(), size=(64, 48), background="black")
    assert black[0, 0].tolist() == [0, 0, 0, 255]


def test_row_0_is_the_top_and_column_0_the_left():
    # The right triangle x, y >= 0, x + y <= 1 seen from the front (+x right, +y up) fills the lower left
    # half of the square from (5, 5) to (95, 95); the upper right corner stays empty.
    triangle = dlfl.Mesh.from_arrays([[0, 0, 0], [1, 0, 0], [0, 1, 0]], [[0, 1, 2]])
    alpha = dlfl.render(triangle, size=(100, 100), view="front", transparent=True)[..., 3]
    assert alpha[10, 10] == alpha[90, 10] == alpha[90, 90] == 255  # top left, bottom left, bottom right
    assert alpha[10, 90] == 0  # top right


def test_a_live_editor_mesh_is_drawn_as_it_is_now():
    ed = dlfl.Editor(unit_cube())
    before = dlfl.render(ed.mesh, size=(60, 40))
    assert np.array_equal(before, dlfl.render(unit_cube(), size=(60, 40)))
    ed.extrude_face(face=1, distance=2.0)
    assert np.array_equal(dlfl.render(ed.mesh, size=(60, 40)), dlfl.render(ed.mesh.copy(), size=(60, 40)))
    assert not np.array_equal(dlfl.render(ed.mesh, size=(60, 40)), before)


def test_a_cell_complex_quad_covers_its_square():
    # One quad 2-cell, the unit square in z = 0 (tensor-product order v00, v10, v01, v11).
    quad = dlfl.CellComplex.from_arrays([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0]], [[0, 1, 2, 3]])
    picture = dlfl.render(quad, size=(100, 100), view="front", edges=False, transparent=True)
    assert coverage(picture) == pytest.approx(90 * 90, rel=0.01)
    with pytest.raises(dlfl.ParameterError) as e:
        dlfl.render(quad, color_by="component")  # a complex has no components to colour
    assert e.value.parameter == "color_by"


def test_files_by_extension(tmp_path):
    assert dlfl.render(unit_cube(), tmp_path / "cube.png", size=(30, 20)) is None
    assert (tmp_path / "cube.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    dlfl.render(unit_cube(), str(tmp_path / "CUBE.PNG"), size=(30, 20))  # either case, str or path
    assert (tmp_path / "CUBE.PNG").read_bytes() == (tmp_path / "cube.png").read_bytes()
    # SVG: from the front only the front face of a closed cube is drawn (the side faces are edge-on, the
    # back face is hidden), a square from (5, 5) to (95, 95).
    dlfl.render(unit_cube(), tmp_path / "cube.svg", size=(100, 100), view="front")
    svg = (tmp_path / "cube.svg").read_text()
    assert svg.count("<polygon") == 1
    assert 'width="100" height="100"' in svg
    assert all(corner in svg for corner in ("5.00,95.00", "95.00,95.00", "95.00,5.00", "5.00,5.00"))


@pytest.mark.parametrize(
    "settings, parameter",
    [
        ({"view": "sideways"}, "view"),
        ({"size": (0, 10)}, "size"),
        ({"size": (16385, 10)}, "size"),
        ({"size": (10000, 10000)}, "size"),  # more than 2^26 pixels
        ({"size": (10, 10, 10)}, "size"),
        ({"size": (10.5, 10)}, "size"),
        ({"size": "10x10"}, "size"),
        ({"zoom": 0}, "zoom"),
        ({"zoom": 1001}, "zoom"),
        ({"azimuth": math.inf}, "azimuth"),
        ({"elevation": math.nan}, "elevation"),
        ({"color_by": "rainbow"}, "color_by"),
        ({"color_by": "attribute=nope"}, "color_by"),  # found once the mesh is read, still before writing
        ({"background": "#12345"}, "background"),
    ],
)
def test_a_bad_setting_names_its_parameter_and_writes_nothing(tmp_path, settings, parameter):
    out = tmp_path / "picture.png"
    with pytest.raises(dlfl.ParameterError) as e:
        dlfl.render(unit_cube(), out, **settings)
    assert e.value.parameter == parameter
    assert str(e.value).startswith(parameter + ":")
    assert not out.exists()
    with pytest.raises(dlfl.ParameterError):
        dlfl.render(unit_cube(), **settings)  # the same without a file


def test_another_extension_names_the_path_and_writes_nothing(tmp_path):
    out = tmp_path / "picture.jpg"
    with pytest.raises(dlfl.InvalidArgument) as e:
        dlfl.render(unit_cube(), out)
    assert str(out) in str(e.value) and ".png or .svg" in str(e.value)
    assert not out.exists()
    assert list(tmp_path.iterdir()) == []  # no temporary file left either


def test_only_meshes_and_cell_complexes_are_drawn():
    with pytest.raises(TypeError, match="dlfl.Mesh or a dlfl.CellComplex"):
        dlfl.render([[0, 0, 0]])
