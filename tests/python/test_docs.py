"""The Python of the docs runs as written: docs/python.md's worked example (printing the figures the page
shows), the README's snippet, the package docstring's example and every call a docstring shows."""
import ast
import inspect
import os
import re
import warnings

import pytest

from conftest import SOURCE_DIR, shared

DOC = SOURCE_DIR / "docs" / "python.md"


def python_blocks(text):
    return re.findall(r"```python\n(.*?)```", text, flags=re.S)


def test_the_worked_example_runs_and_prints_what_the_page_says(tmp_path, monkeypatch, capsys):
    pytest.importorskip("matplotlib", reason="matplotlib is absent (scripts/test-tools puts it in python-venv)")
    merl = shared("merl", "alum-bronze.binary.xz").parent
    (tmp_path / "materials").symlink_to(SOURCE_DIR / "materials")
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("GLOSSY_MERL_DIR", str(merl))
    text = DOC.read_text()
    blocks = python_blocks(text)
    assert len(blocks) >= 3
    namespace = {}
    for block in blocks:
        exec(compile(block, str(DOC), "exec"), namespace)
    for output in ["theta_h.png", "sheet.png", "alum-bronze.exr", "alum-bronze.png"]:
        assert (tmp_path / output).stat().st_size > 1000, output
    printed = capsys.readouterr().out
    # The page's "prints" block, but for where the table lives.
    shown = re.search(r"prints\n\n```text\n(.*?)```", text, flags=re.S).group(1)
    for line in shown.splitlines():
        if "…" not in line:
            assert line in printed.splitlines(), line
    assert namespace["sheet"].figures["cook_torrance_E2"]["relative_rmse"] > 0


def test_the_readme_snippet_runs_from_the_checkout(monkeypatch):
    import glossy
    monkeypatch.chdir(SOURCE_DIR)
    monkeypatch.delenv("GLOSSY_MERL_DIR", raising=False)   # a fresh clone: the networks beside the materials
    blocks = python_blocks((SOURCE_DIR / "README.md").read_text())
    assert len(blocks) == 1
    namespace = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", glossy.GlossyWarning)
        exec(compile(blocks[0], "README.md", "exec"), namespace)
    assert namespace["rho"].shape == (1, 3) and (namespace["rho"] > 0).all()
    assert namespace["image"].shape == (256, 256, 3)


def test_the_package_docstring_example_runs_from_the_checkout(monkeypatch):
    import glossy
    monkeypatch.chdir(SOURCE_DIR)
    monkeypatch.delenv("GLOSSY_MERL_DIR", raising=False)
    example = re.search(r"\n((?:    .*\n)+)", glossy.__doc__).group(1)
    assert "import glossy" in example
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", glossy.GlossyWarning)
        exec(compile(inspect.cleandoc(example), "glossy.__doc__", "exec"), {})


def docstring_calls():
    """Every `glossy.NAME(...)` a docstring of the package shows with literal arguments only."""
    import glossy
    docs = [glossy.__doc__]
    for name in glossy.__all__:
        obj = getattr(glossy, name)
        docs.append(getattr(obj, "__doc__", None) or "")
        if isinstance(obj, type):
            docs += [getattr(member, "__doc__", None) or "" for _, member in inspect.getmembers(obj)]
    calls = set()
    for doc in docs:
        for start in re.finditer(r"glossy\.[a-z_]+\(", doc):
            depth, end = 0, start.end() - 1
            for end in range(start.end() - 1, len(doc)):
                depth += {"(": 1, ")": -1}.get(doc[end], 0)
                if depth == 0:
                    break
            text = doc[start.start():end + 1]
            try:
                call = ast.parse(text, mode="eval").body
                for arg in [*call.args, *(k.value for k in call.keywords)]:
                    ast.literal_eval(arg)
            except (SyntaxError, ValueError):
                continue   # a call with names in it (glossy.uniforms(N, seed)) illustrates, it is not an example
            if call.args or call.keywords:
                calls.add(text)
    return sorted(calls)


def test_every_docstring_example_call_runs(monkeypatch):
    import glossy
    monkeypatch.chdir(SOURCE_DIR)
    calls = docstring_calls()
    assert any(c.startswith("glossy.make_brdf(") for c in calls), calls
    for call in calls:
        eval(call, {"glossy": glossy})


def test_the_messages_the_page_quotes_are_the_ones_raised(monkeypatch):
    import glossy
    monkeypatch.chdir(SOURCE_DIR)
    text = " ".join(DOC.read_text().split())
    missing_fit, bad_spp = re.search(r"with the line `glossy` prints for the same input: `([^`]*)`.*?"
                                     r"with their Python names: `([^`]*)`", text).groups()
    material = glossy.load_material("materials/library/merl/alum-bronze.toml")
    with pytest.raises(glossy.InputError) as raised:
        material.brdf(missing_fit.split("has no ")[1].split(" fit")[0])
    assert str(raised.value) == missing_fit
    with pytest.raises(glossy.InputError) as raised:
        glossy.render(brdf=material.brdf("cook-torrance:E2"), spp=0)
    assert str(raised.value) == bad_spp
