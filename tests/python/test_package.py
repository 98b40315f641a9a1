"""The package as editors and help() see it: every public name typed in __init__.pyi and documented."""
import ast
from pathlib import Path

import glossy


def stub_names():
    tree = ast.parse((Path(glossy.__file__).parent / "__init__.pyi").read_text())
    names, members = set(), {}
    for node in tree.body:
        if isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        if isinstance(node, ast.ClassDef):
            members[node.name] = {n.name for n in node.body if isinstance(n, ast.FunctionDef)}
            for base in node.bases:  # what a class inherits from another of the stubs
                if isinstance(base, ast.Name) and base.id in members:
                    members[node.name] |= members[base.id]
        if isinstance(node, ast.AnnAssign):
            names.add(node.target.id)
    return names, members


def test_stubs_name_exactly_the_public_api():
    names, members = stub_names()
    assert names == set(glossy.__all__)
    for cls, stubbed in members.items():
        if issubclass(getattr(glossy, cls), BaseException):
            continue
        public = {n for n in dir(getattr(glossy, cls)) if not n.startswith("_")}
        assert stubbed == public, cls


def test_every_public_name_is_documented():
    for name in glossy.__all__:
        if name.startswith("__"):
            continue
        obj = getattr(glossy, name)
        assert obj.__doc__ and len(obj.__doc__.strip()) > 20, name
    assert glossy.__doc__ and "docs/python.md" in glossy.__doc__
