"""The type stub (__init__.pyi, written by the build) names every public function, class and method, and
types the generated operation methods."""

import ast
import inspect
import pathlib

import dlfl

STUB = pathlib.Path(dlfl.__file__).with_name("__init__.pyi")


def stub_tree():
    return ast.parse(STUB.read_text())


def test_the_stub_names_everything_public():
    tree = stub_tree()
    top = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    top |= {t.id for n in tree.body if isinstance(n, ast.AnnAssign) for t in [n.target]}
    assert set(dlfl.__all__) <= top
    classes = {n.name: n for n in tree.body if isinstance(n, ast.ClassDef)}
    for cls in (dlfl.Mesh, dlfl.Editor, dlfl.CellComplex):
        stubbed = {n.name for n in classes[cls.__name__].body if isinstance(n, ast.FunctionDef)}
        public = {name for name in dir(cls) if not name.startswith("_")}
        assert public <= stubbed, public - stubbed


def test_generated_methods_are_typed_from_their_declarations():
    editor = next(n for n in stub_tree().body if isinstance(n, ast.ClassDef) and n.name == "Editor")
    methods = {n.name: n for n in editor.body if isinstance(n, ast.FunctionDef)}
    for op in dlfl.operations():
        method = getattr(dlfl.Editor, op["name"])
        if not inspect.isfunction(method):
            continue
        stub = methods[op["name"]]
        names = [a.arg for a in stub.args.args + stub.args.kwonlyargs][1:]
        assert names == list(inspect.signature(method).parameters)[1:]
    insert_edge = methods["insert_edge"]
    assert [ast.unparse(a.annotation) for a in insert_edge.args.args[1:]] == ["int", "int"]
    smooth = methods["smooth"]
    assert [a.arg for a in smooth.args.args[1:]] == ["iterations", "lambda_", "keep_boundary"]
