"""The exceptions of dlfl, mirroring the C++ hierarchy of dlfl/errors.h.

Every error the library raises on purpose is a :class:`Error`; messages are the library's own. The extension
module raises these classes with their fields filled in.
"""

from __future__ import annotations


class Error(Exception):
    """Base of every error the library raises on purpose (``dlfl::Error``)."""


class InvalidArgument(Error, ValueError):
    """An argument is out of its documented range: a removed handle, a bad parameter value
    (``dlfl::InvalidArgument``). Also a :class:`ValueError`."""


class ParameterError(InvalidArgument):
    """A named parameter of an operation or scheme is unknown, missing, of the wrong type or out of its range
    (``dlfl::ParameterError``). ``parameter`` is its name ("params.t" for a nested one), or None."""

    def __init__(self, message: str, parameter: str | None = None) -> None:
        super().__init__(message)
        self.parameter = parameter


class UnknownNameError(InvalidArgument):
    """No operation or scheme has that name (``dlfl::UnknownNameError``). ``suggestion`` is a close known
    name, or None."""

    def __init__(self, message: str, suggestion: str | None = None) -> None:
        super().__init__(message)
        self.suggestion = suggestion


class TopologyError(Error):
    """An operation would break the 2-manifold, or is not defined on the given elements
    (``dlfl::TopologyError``)."""


class PolygonError(TopologyError):
    """A polygon list that is not an orientable 2-manifold (``dlfl::PolygonError``): ``element`` is "face" or
    "vertex" and ``index`` its index in the input."""

    def __init__(self, message: str, element: str | None = None, index: int | None = None) -> None:
        super().__init__(message)
        self.element = element
        self.index = index


class IoError(Error):
    """Reading or writing a file failed, or its content is malformed (``dlfl::IoError``). ``path`` is the
    file and ``line`` the 1-based line to blame, each None when unknown."""

    def __init__(self, message: str, path: str | None = None, line: int | None = None) -> None:
        super().__init__(message)
        self.path = path
        self.line = line


class LogError(IoError):
    """An operation log that cannot be replayed (``dlfl::LogError``). ``op_index`` is the index of the
    offending op (None for the document itself) and ``field`` the field at fault ("corner1", "params.t"),
    or None."""

    def __init__(
        self,
        message: str,
        path: str | None = None,
        line: int | None = None,
        op_index: int | None = None,
        field: str | None = None,
    ) -> None:
        super().__init__(message, path, line)
        self.op_index = op_index
        self.field = field


__all__ = [
    "Error",
    "InvalidArgument",
    "ParameterError",
    "UnknownNameError",
    "TopologyError",
    "PolygonError",
    "IoError",
    "LogError",
]

# Shown (and pickled) as dlfl.NAME, where the package exports them.
for _name in __all__:
    globals()[_name].__module__ = "dlfl"
del _name
