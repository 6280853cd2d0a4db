"""Writes the dlfl stub: the hand-written template with one Editor method per operation that the package
generates from the registry, typed from the declarations. Run by the build with the module just built:

    PYTHONPATH=build/python python3 python/tools/stubgen.py python/dlfl/__init__.pyi.in build/python/dlfl/__init__.pyi
"""

import inspect
import sys

import dlfl

# Python types of the declared parameter types (dlfl/parameters.h, ParamType).
TYPES = {
    "boolean": "bool",
    "integer": "int",
    "number": "float",
    "text": "str",
    "point": "Sequence[float]",
    "vertex": "int",
    "edge": "int",
    "face": "int",
    "corner": "int",
    "vertices": "int | Sequence[int] | npt.ArrayLike",
    "edges": "int | Sequence[int] | npt.ArrayLike",
    "faces": "int | Sequence[int] | npt.ArrayLike",
    "corners": "int | Sequence[int] | npt.ArrayLike",
    "numbers": "float | Sequence[float] | npt.ArrayLike",
    "points": "npt.ArrayLike",
    "mesh": "Mesh",
    "params": "dict[str, Any]",
}


def annotation(param):
    text = TYPES[param["type"]]
    if param["keywords"] and param["type"] != "text":
        text += " | str"  # a keyword in place of a value ("centroid")
    if param["default"] is None and param["optional"]:
        text += " | None"
    return text


def method_stub(op, method):
    declared = {p["name"]: p for p in op["params"]}
    declared.update({p["name"] + "_": p for p in op["params"]})  # keywords: lambda_
    parts = ["self"]
    keyword_only = False
    for p in list(inspect.signature(method).parameters.values())[1:]:
        if p.kind is inspect.Parameter.KEYWORD_ONLY and not keyword_only:
            parts.append("*")
            keyword_only = True
        default = "" if p.default is inspect.Parameter.empty else " = ..."
        parts.append(f"{p.name}: {annotation(declared[p.name])}{default}")
    return f"    def {op['name']}({', '.join(parts)}) -> dict[str, Any]: ..."


def main(template_path, output_path):
    lines = []
    for op in dlfl.operations():
        method = dlfl.Editor.__dict__.get(op["name"])
        if inspect.isfunction(method) and getattr(method, "__signature__", None) is not None:
            lines.append(method_stub(op, method))
        elif inspect.isfunction(method):  # a parameter name that is no identifier: keywords only
            lines.append(f"    def {op['name']}(self, *args: Any, **kwargs: Any) -> dict[str, Any]: ...")
    with open(template_path, encoding="utf-8") as f:
        template = f.read()
    marker = "    # @operations\n"
    if marker not in template:
        sys.exit(f"{template_path}: no '# @operations' line in class Editor")
    stub = template.replace(marker, "    # The registered operations (generated).\n" + "\n".join(lines) + "\n")
    with open(output_path, "w", encoding="utf-8") as f:
        f.write(stub)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
