"""The type stubs (hexc/__init__.pyi) declare every public function and Context method of the package with the
parameters it takes, in order; a stub missing a parameter (the negative control) fails the comparison."""
import ast
import inspect
import os

import hexc


def stub_signatures(tree):
    """{"name" or "Class.name": [parameter names]} of the stub's functions and methods."""
    found = {}
    for node in tree.body:
        members = [(node.name + ".", n) for n in node.body] if isinstance(node, ast.ClassDef) else [("", node)]
        for prefix, f in members:
            if isinstance(f, ast.FunctionDef):
                a = f.args
                found[prefix + f.name] = [p.arg for p in a.posonlyargs + a.args + a.kwonlyargs]
    return found


def module_signatures():
    found = {}
    for name in hexc.__all__:
        value = getattr(hexc, name)
        if inspect.isfunction(value):
            found[name] = list(inspect.signature(value).parameters)
    for name, method in inspect.getmembers(hexc.Context, inspect.isfunction):
        if not name.startswith("_") or name == "__init__":
            found["Context." + name] = list(inspect.signature(method).parameters)
    return found


def test_stubs_declare_the_package():
    stub = os.path.join(os.path.dirname(hexc.__file__), "__init__.pyi")
    declared = stub_signatures(ast.parse(open(stub).read()))
    module = module_signatures()
    # The module's `**options` functions pass their keywords on to Context: the stub spells them out.
    for name, parameters in module.items():
        if parameters[-1:] == ["options"]:
            assert declared[name][:len(parameters) - 1] == parameters[:-1], name
            assert set(declared[name]) >= set(declared["Context." + name][1:]), name
        else:
            assert declared.get(name) == parameters, name
    # Negative control: a parameter left out of a stub is found.
    declared["Context.render"].remove("uv_rect")
    assert declared["Context.render"] != module["Context.render"]
