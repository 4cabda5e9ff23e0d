"""The shipped stubs (oflab/__init__.pyi) name exactly the module's members: every public
function and class, and every method and property of each class."""

import ast
import os

import oflab

STUBS = os.path.join(os.path.dirname(oflab.__file__), "__init__.pyi")


def stub_tree():
    with open(STUBS, encoding="utf-8") as f:
        return ast.parse(f.read())


def members(cls):
    return {name for name in dir(cls)
            if not name.startswith("__") and not hasattr(object, name)
            and name not in ("_pybind11_conduit_v1_",)}


def stub_members(node):
    return {n.name for n in node.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}


def test_the_stubs_name_every_function_and_class_of_the_module():
    tree = stub_tree()
    stubbed = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    public = {name for name in dir(oflab) if not name.startswith("__") and name != "annotations"
              and not isinstance(getattr(oflab, name), type(os))}
    assert stubbed == public


def test_the_stubs_name_every_member_of_each_class():
    for node in stub_tree().body:
        if not isinstance(node, ast.ClassDef):
            continue
        cls = getattr(oflab, node.name)
        own = members(cls)
        if node.name == "Picture":  # an ndarray: the stub names what it adds
            own = set(vars(cls)) - {"__module__", "__doc__", "__dict__", "__weakref__"}
        assert stub_members(node) == own, node.name


def test_a_missing_member_would_be_seen():
    """Negative control: a stub without one of the module's functions differs."""
    tree = stub_tree()
    stubbed = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)} - {"flow"}
    assert "flow" in dir(oflab) and "flow" not in stubbed
