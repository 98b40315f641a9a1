"""docs/python.md's worked example runs as written, and prints the figures the page shows."""
import os
import re

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
