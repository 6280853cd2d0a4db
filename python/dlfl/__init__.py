"""dlfl: topological modelling and subdivision on the Doubly Linked Face List, from Python.

    import dlfl
    mesh = dlfl.read_mesh("data/dodecahedron.obj")
    fine = dlfl.subdivide(mesh, "honeycomb", iterations=2, t=0.5)
    fine.positions                       # (V, 3) float64, a read-only view of the mesh's storage
    ed = dlfl.Editor(mesh)
    ed.insert_edge(0, 2)                 # every registered operation is a method (dlfl.operations())
    with ed.group("a handle"):
        ...
    ed.undo()
    ed.write_log("session.json")         # `dlfl replay session.json -o out.obj` gives the same mesh
    dlfl.render(fine, "fine.png", view="front")  # or, without a path, an (h, w, 4) uint8 RGBA array

Handles (vertices, edges, faces, corners) are ints. Errors are dlfl.Error and its subclasses, which mirror
the C++ library's. The compiled part is dlfl._dlfl; this package adds the Editor's operation methods
(generated from the operation registry, so that every registered operation appears with its parameters
and defaults) and Editor.group. See docs/python.md.
"""

from __future__ import annotations

import contextlib
import inspect
import keyword
from typing import Any, Iterator

from ._dlfl import (
    CellComplex,
    Editor,
    Mesh,
    __version__,
    info,
    mlca_subdivide,
    operations,
    read_cell_complex,
    read_mesh,
    render,
    replay,
    schemes,
    subdivide,
    validate,
    write_cell_complex,
    write_mesh,
)
from ._errors import (
    Error,
    InvalidArgument,
    IoError,
    LogError,
    ParameterError,
    PolygonError,
    TopologyError,
    UnknownNameError,
)


@contextlib.contextmanager
def _group(self: Editor, label: str = "") -> Iterator[Editor]:
    """Everything applied inside the ``with`` block is one undo entry labelled ``label``: begin_group on
    entry, end_group on exit. The group is ended even when the block raises; the exception then propagates,
    and the operations that succeeded before it stay in the group's entry (one ``undo()`` takes them all
    back). Groups nest; the outermost one makes the entry."""
    self.begin_group(label)
    try:
        yield self
    finally:
        self.end_group()


Editor.group = _group
for _cls in (CellComplex, Editor, Mesh):
    _cls.__module__ = "dlfl"  # shown as dlfl.Mesh, where the package exports them
del _cls


def _describe(param: dict[str, Any]) -> str:
    """One line of an operation's docstring for a parameter, from its declaration."""
    if param["default"] is not None:
        default = f"default {param['default']!r}"
    elif param["optional"]:
        default = "optional" + (f": {param['default_doc']}" if param.get("default_doc") else "")
    else:
        default = "required"
    allowed = ""
    if "range" in param:
        r = param["range"]
        low = "(" if r["min_open"] else "["
        high = ")" if r["max_open"] else "]"
        lo = "-inf" if r["min"] is None else r["min"]
        hi = "inf" if r["max"] is None else r["max"]
        allowed = f", in {low}{lo}, {hi}{high}"
    if param["keywords"]:
        allowed += ", " + ("one of " if param["type"] == "text" else "or ") + ", ".join(
            repr(k) for k in param["keywords"]
        )
    return f"    {param['name']} ({param['type']}, {default}{allowed}): {param['doc']}"


def _signature(op: dict[str, Any]) -> inspect.Signature | None:
    """The method's signature for help() and editors: declared order and defaults. A parameter named like a
    Python keyword gets a trailing underscore (smooth's lambda is lambda_), as Editor.apply accepts it. A
    required parameter after one with a default is shown keyword-only (it may still be given positionally).
    None if a name is not a Python identifier."""
    kind = inspect.Parameter.POSITIONAL_OR_KEYWORD
    params = [inspect.Parameter("self", kind)]
    for p in op["params"]:
        if p["default"] is not None:
            default = p["default"]
        elif p["optional"]:
            default = None
        else:
            default = inspect.Parameter.empty
        if default is inspect.Parameter.empty and params[-1].default is not inspect.Parameter.empty:
            kind = inspect.Parameter.KEYWORD_ONLY
        try:
            name = p["name"] + "_" if keyword.iskeyword(p["name"]) else p["name"]
            params.append(inspect.Parameter(name, kind, default=default))
        except ValueError:
            return None
    return inspect.Signature(params)


def _operation_method(op: dict[str, Any]):
    """Editor.NAME(*args, **kwargs): Editor.apply("NAME", ...), documented from the declaration."""
    name = op["name"]

    def method(self: Editor, *args: Any, **kwargs: Any) -> dict[str, Any]:
        return self.apply(name, *args, **kwargs)

    method.__name__ = method.__qualname__ = name
    lines = [op["doc"][:1].upper() + op["doc"][1:] + ".", ""]
    if op["counts"]:
        lines += [f"Counts: {op['counts']}.", ""]
    lines += ["Parameters:"] + [_describe(p) for p in op["params"]] if op["params"] else ["No parameters."]
    lines += ["", f"Returns the operation's outputs as a dict; one undo entry ({op['kind']} operation)."]
    method.__doc__ = "\n".join(lines)
    signature = _signature(op)
    if signature is not None:
        method.__signature__ = signature
    return method


# Every registered operation becomes a method, unless the Editor already has one of that name (mesh, the
# current mesh, is a property; subdivide, undo and redo have their own signatures): apply() reaches those.
for _op in operations():
    if not hasattr(Editor, _op["name"]):
        setattr(Editor, _op["name"], _operation_method(_op))
del _op

__all__ = [
    "CellComplex",
    "Editor",
    "Error",
    "InvalidArgument",
    "IoError",
    "LogError",
    "Mesh",
    "ParameterError",
    "PolygonError",
    "TopologyError",
    "UnknownNameError",
    "__version__",
    "info",
    "mlca_subdivide",
    "operations",
    "read_cell_complex",
    "read_mesh",
    "render",
    "replay",
    "schemes",
    "subdivide",
    "validate",
    "write_cell_complex",
    "write_mesh",
]
