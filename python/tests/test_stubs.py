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


def missing_and_extra(tree):
    """Names of the module the stubs lack, and names of the stubs the module lacks: the
    package's public names (__all__, which holds every name without a leading underscore) and
    every member of the compiled module _oflab."""
    stubbed = {n.name for n in tree.body if isinstance(n, (ast.FunctionDef, ast.ClassDef))}
    public = {name for name in dir(oflab) if not name.startswith("_")
              and not isinstance(getattr(oflab, name), type(os))}
    assert public == set(oflab.__all__)
    compiled = {name for name in dir(oflab._oflab) if not name.startswith("__")}
    return (public | compiled) - stubbed, stubbed - (public | compiled)


def class_differences(tree):
    """Per stubbed class, the members that differ between the stub and the class."""
    differences = {}
    for node in tree.body:
        if not isinstance(node, ast.ClassDef):
            continue
        cls = getattr(oflab, node.name)
        own = members(cls)
        if node.name == "Picture":  # an ndarray: the stub names what it adds
            own = set(vars(cls)) - {"__module__", "__doc__", "__dict__", "__weakref__"}
        if stub_members(node) != own:
            differences[node.name] = stub_members(node) ^ own
    return differences


def test_the_stubs_name_every_function_and_class_of_the_module():
    assert missing_and_extra(stub_tree()) == (set(), set())


def test_the_stubs_name_every_member_of_each_class():
    assert class_differences(stub_tree()) == {}


def test_a_missing_or_stale_stub_is_seen():
    """Negative controls: the same checks on stubs with a function and a property removed
    and a stale function added."""
    tree = stub_tree()
    tree.body = [n for n in tree.body if getattr(n, "name", None) != "flow"]
    tree.body.append(ast.parse("def gone() -> None: ...").body[0])
    assert missing_and_extra(tree) == ({"flow"}, {"gone"})
    run = next(n for n in tree.body if getattr(n, "name", None) == "Run")
    run.body = [n for n in run.body if getattr(n, "name", None) != "holes"]
    assert class_differences(tree) == {"Run": {"holes"}}
