"""What the Python tests share: the glossy executable they compare with, the data folders, and running it.

CTest runs each test_*.py here with the build's package on PYTHONPATH (tests/CMakeLists.txt); the
reference data come from ../shared, and a test whose data is absent is skipped, saying so.
"""
import os
import subprocess
from pathlib import Path

import pytest

SOURCE_DIR = Path(os.environ.get("GLOSSY_SOURCE_DIR", Path(__file__).resolve().parents[2]))
SHARED_DIR = Path(os.environ.get("GLOSSY_SHARED_DIR", SOURCE_DIR.parent / "shared"))
EXE = os.environ.get("GLOSSY_EXE", str(SOURCE_DIR / "build/renderer/glossy"))


def run_cli(*args, stdin=None, check=True):
    """Runs glossy; returns the CompletedProcess (text)."""
    done = subprocess.run([EXE, *map(str, args)], input=stdin, capture_output=True, text=True)
    if check and done.returncode != 0:
        raise AssertionError(f"glossy {' '.join(map(str, args))} failed ({done.returncode}): {done.stderr}")
    return done


def cli_error(*args, stdin=None):
    """The one line glossy prints for bad input (exit status 2), without its 'glossy: ' prefix."""
    done = run_cli(*args, stdin=stdin, check=False)
    assert done.returncode == 2, f"expected exit status 2, got {done.returncode}: {done.stderr}"
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1, done.stderr
    assert lines[0].startswith("glossy: ")
    return lines[0][len("glossy: "):]


def material_path(name):
    return SOURCE_DIR / "materials" / "library" / "merl" / f"{name}.toml"


def shared(*parts):
    """A file of ../shared, or a skip naming it."""
    path = SHARED_DIR.joinpath(*parts)
    if not path.exists():
        pytest.skip(f"{path} is absent: this test needs the shared reference data")
    return path
