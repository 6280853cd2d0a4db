"""Shared set-ups of the Python suite: where the bundled data and the dlfl tool are. CTest sets DLFL_DATA and
DLFL_TOOL (python/CMakeLists.txt) and PYTHONPATH to the build tree's package; the meshes are in meshes.py."""

import os
import pathlib

import pytest

DATA = pathlib.Path(os.environ.get("DLFL_DATA", pathlib.Path(__file__).resolve().parents[2] / "data"))


@pytest.fixture
def data():
    return DATA


@pytest.fixture
def tool():
    path = os.environ.get("DLFL_TOOL")
    assert path, "DLFL_TOOL names the dlfl tool (CTest sets it when the tool is built)"
    return path
