"""A study's results as NumPy arrays and dicts: what `glossy study` wrote into its output folder, read back.

The folder's layout is the command's (docs/study.md): `study.json` (the plan), `analysis/rows.json` (one row
per material × lighting × scene × model, the columns of `rows.csv`), `analysis/results.json` (every
statistic) and `analysis/summary.md`. The columns are named as `rows.csv` names them and their values read
from `rows.json`, which keeps each value's type: a figure the sheet has not got is `null` there, an empty
field in the CSV.
"""
import csv
import json
import math
import os
import re
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from . import _core

def _safe(text):
    """`text` as one safe line, as every glossy message quotes names: control characters escaped, a long one
    cut around its middle (the library's safeLine)."""
    return _core._safe_line(str(text), 200)


def _snake(key):
    return re.sub(r"([A-Z])", lambda m: "_" + m.group(1).lower(), key)


def _read_json(path, what):
    if not path.is_file() or path.is_symlink():
        raise _core.InputError(f"{_safe(path)}: no {what} here (a folder `glossy study -o` wrote has one)")
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f, parse_constant=lambda name: math.nan)
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as e:
        raise _core.InputError(f"{_safe(path)}: not the {what} glossy writes ({_safe(e)})") from None


def _column(name, values, path):
    """One column of the rows as an array: flags as bool, whole numbers as int64, figures as float64 with
    NaN where a row has none, anything else as str."""
    present = [v for v in values if v is not None]
    if all(isinstance(v, bool) for v in present) and len(present) == len(values):
        return np.array(values, dtype=bool)
    if all(isinstance(v, int) and not isinstance(v, bool) for v in present) and len(present) == len(values):
        return np.array(values, dtype=np.int64)
    if all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in present):
        return np.array([math.nan if v is None else float(v) for v in values], dtype=np.float64)
    if all(isinstance(v, str) for v in present):
        return np.array(["" if v is None else v for v in values], dtype=str)
    raise _core.InputError(f"{_safe(path)}: column '{_safe(name)}' mixes kinds of value")


@dataclass(frozen=True)
class Study:
    """A study's output folder, read: `glossy.read_study(OUT)`."""

    folder: Path
    """The output folder."""
    plan: dict
    """study.json: the materials, lightings and scenes the study planned."""
    rows: dict = field(repr=False)
    """One NumPy array per column of rows.csv (same names, same order), one entry per row; figures are
    float64 with NaN where the sheet has none (`pandas.DataFrame(study.rows)` makes a table of them)."""
    results: dict = field(repr=False)
    """results.json: every statistic, as the command wrote it."""
    summary: str = field(repr=False)
    """summary.md."""


def study(file, output, *, shard=None, analyse=False, merl_dir=None, threads=None):
    """Runs a study as `glossy study FILE -o OUTPUT` does — the same checks, sheets and analysis, the same
    bytes in OUTPUT — and returns its results, read_study(OUTPUT). Sheets already complete are kept, so a
    run stopped by Ctrl-C resumes where it was.

    shard: "i/N" renders only shard i (0-based) of N, the sheets split by expected cost, and returns None:
    once every shard is done, study(file, output, analyse=True) analyses them (every sheet must be
    complete); None: the job array's task when run as one (Slurm, a Kubernetes indexed Job, AWS Batch;
    docs/cluster.md), else every sheet. merl_dir: MERL tables (else $GLOSSY_MERL_DIR). threads: unset, the
    study file's settings.threads. Raises InputError (the command's one line) for bad input, before any work, and
    RuntimeError when sheets are still being written by another run or, with analyse, are not complete."""
    ended = _core._study(file, output, shard=shard, analyse=analyse, merl_dir=merl_dir, threads=threads)
    if ended == "analysed":
        return read_study(output)
    if ended == "shard done":
        return None
    if ended == "busy":
        raise RuntimeError(f"{_safe(output)}: some sheets are being written by another run; run again to analyse")
    raise RuntimeError(f"{_safe(output)}: not every sheet is complete: render them first (study without analyse)")


def read_study(folder):
    """Reads what `glossy study STUDY -o FOLDER` (or `glossy.study`) wrote: its plan, its rows as NumPy
    arrays and its results as dicts. Raises InputError naming the file when the folder is not an analysed
    study's (run the study, or `glossy study STUDY -o FOLDER --analyse` after its shards)."""
    folder = Path(os.fspath(folder))
    if not folder.is_dir():
        raise _core.InputError(f"{_safe(folder)}: not a folder (a study's output folder, `glossy study -o`)")
    plan = _read_json(folder / "study.json", "study plan")
    analysis = folder / "analysis"
    rows_path = analysis / "rows.json"
    rows = _read_json(rows_path, "study rows")
    results = _read_json(analysis / "results.json", "study results")
    if not isinstance(rows, list) or not all(isinstance(r, dict) for r in rows):
        raise _core.InputError(f"{_safe(rows_path)}: not the study rows glossy writes (a list of rows)")
    if not isinstance(results, dict) or not isinstance(plan, dict):
        raise _core.InputError(f"{_safe(folder)}: study.json or analysis/results.json is not the object glossy writes")
    csv_path = analysis / "rows.csv"
    try:
        with open(csv_path, encoding="utf-8", newline="") as f:
            names = next(csv.reader(f), [])
    except (OSError, UnicodeDecodeError, csv.Error) as e:
        raise _core.InputError(f"{_safe(csv_path)}: not the study rows glossy writes ({_safe(e)})") from None
    # rows.json's keys are rows.csv's columns in camel case (materialClass: material_class).
    for k, row in enumerate(rows):
        if [_snake(key) for key in row] != names:
            raise _core.InputError(f"{_safe(rows_path)}: row {k}'s fields are not the columns of {_safe(csv_path.name)}")
    values = [list(row.values()) for row in rows]
    columns = {name: _column(name, [v[n] for v in values], rows_path) for n, name in enumerate(names)}
    summary_path = analysis / "summary.md"
    summary = summary_path.read_text(encoding="utf-8") if summary_path.is_file() else ""
    return Study(folder=folder, plan=plan, rows=columns, results=results, summary=summary)
