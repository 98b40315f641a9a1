"""glossy.read_study: a study's output folder as the command wrote it, read back into arrays and dicts — every
row and column of rows.csv, results.json and the plan unchanged — and a folder that is not one refused in
one line naming the file."""
import csv
import json
import math

import numpy as np
import pytest

import glossy
from conftest import SOURCE_DIR, run_cli

# Two materials of two databases under two lightings, three models: seconds (docs/study.md shows it).
TINY_STUDY = (SOURCE_DIR / "scenes" / "studies" / "tiny.toml").read_text()


@pytest.fixture(scope="module")
def study_folder(tmp_path_factory):
    root = tmp_path_factory.mktemp("study")
    (root / "tiny.toml").write_text(TINY_STUDY)
    run_cli("study", root / "tiny.toml", "-o", root / "out")
    return root / "out"


def csv_rows(folder):
    with open(folder / "analysis" / "rows.csv", newline="") as f:
        return list(csv.reader(f))


def test_the_rows_are_rows_csv_column_for_column(study_folder):
    study = glossy.read_study(study_folder)
    header, *lines = csv_rows(study_folder)
    assert list(study.rows) == header
    assert len(lines) == 2 * 2 * 3  # materials × lightings × model panels
    for n, name in enumerate(header):
        column = study.rows[name]
        assert len(column) == len(lines), name
        for value, line in zip(column, lines):
            text = line[n]
            if column.dtype == bool:
                assert text == ("1" if value else "0"), name
            elif column.dtype.kind in "iu":
                assert int(text) == value, name
            elif column.dtype.kind == "f":
                # The CSV prints each figure as its shortest text: it reads back as the same double.
                assert (text == "" and math.isnan(value)) or float(text) == value, name
            else:
                assert text == value, name
    assert study.rows["rrmse"].dtype == np.float64
    assert study.rows["closest"].dtype == bool
    assert study.rows["spp"].dtype == np.int64
    assert set(study.rows["material"]) == {"gold-paint", "bluebook"}
    # r* that the sheets clamped to 0 (their noise-free estimate came out negative) are marked as such.
    clamped = study.rows["rrmse_clamped"]
    assert clamped.dtype == bool and clamped.any()  # at 16² and 16 spp some model is within the noise
    assert (study.rows["rrmse"][clamped] == 0).all()
    assert study.results["counts"]["rowsRrmseClamped"] == clamped.sum()


def test_results_plan_and_summary_are_the_files(study_folder):
    study = glossy.read_study(study_folder)
    assert study.results == json.loads((study_folder / "analysis" / "results.json").read_text())
    assert study.plan == json.loads((study_folder / "study.json").read_text())
    assert study.summary == (study_folder / "analysis" / "summary.md").read_text()
    assert study.folder == study_folder
    # What the summary's headline says is in the results the user can compute with.
    models = {m["label"] for m in study.results["models"]}
    assert models == set(study.rows["label"])


def test_a_folder_that_is_not_an_analysed_study_is_one_line_naming_the_file(study_folder, tmp_path):
    with pytest.raises(glossy.InputError, match=r"nowhere: not a folder"):
        glossy.read_study(tmp_path / "nowhere")
    with pytest.raises(glossy.InputError, match=r"study\.json: no study plan here"):
        glossy.read_study(tmp_path)
    broken = tmp_path / "broken"
    (broken / "analysis").mkdir(parents=True)
    (broken / "study.json").write_text((study_folder / "study.json").read_text())
    with pytest.raises(glossy.InputError, match=r"rows\.json: no study rows here"):
        glossy.read_study(broken)
    for name in ("rows.json", "rows.csv", "results.json"):
        (broken / "analysis" / name).write_bytes((study_folder / "analysis" / name).read_bytes())
    (broken / "analysis" / "rows.json").write_text("[{\"material\": 1")
    with pytest.raises(glossy.InputError, match=r"rows\.json: not the study rows glossy writes"):
        glossy.read_study(broken)
    # Rows of another file's columns: mixed files are refused, not read as some other column.
    rows = json.loads((study_folder / "analysis" / "rows.json").read_text())
    rows[3] = {("spp2" if k == "spp" else k): v for k, v in rows[3].items()}
    (broken / "analysis" / "rows.json").write_text(json.dumps(rows))
    with pytest.raises(glossy.InputError, match=r"row 3's fields are not the columns of rows\.csv"):
        glossy.read_study(broken)
    hostile = tmp_path / "a\x1b[31mred\nline"
    hostile.mkdir()
    with pytest.raises(glossy.InputError) as raised:
        glossy.read_study(hostile)
    assert "\n" not in str(raised.value) and "\x1b" not in str(raised.value)
    assert "\\x1b[31mred\\nline" in str(raised.value)


def test_the_docs_study_example_runs_and_agrees_with_the_results(study_folder, capsys, monkeypatch):
    import runpy
    script = SOURCE_DIR / "docs" / "examples" / "study_headline.py"
    assert f"```python docs/examples/study_headline.py\n{script.read_text()}```" in (SOURCE_DIR / "docs" / "python.md").read_text()
    monkeypatch.setattr("sys.argv", [str(script), str(study_folder)])
    runpy.run_path(str(script), run_name="__main__")
    printed = capsys.readouterr().out.splitlines()
    results = json.loads((study_folder / "analysis" / "results.json").read_text())
    within = next(d for d in results["e2MinusE1"] if d["image"] == "rrmse")["withinMaterialSpearman"]
    assert printed[0].startswith(f"E2 - E1, within a material: {within['estimate']:.3f} ")
    for model, line in zip(results["models"], printed[1:], strict=True):
        assert line.split()[0] == model["label"].split()[0], line
        # The mean r* recomputed from the rows is the one results.json reports.
        assert line.endswith(f"mean r* {model['meanRrmse']['estimate']:.4f}"), line


def outputs(folder):
    """Every file under `folder` (relative path: bytes), but the sheets' EXRs, which record their render time."""
    return {p.relative_to(folder).as_posix(): p.read_bytes() for p in sorted(folder.rglob("*"))
            if p.is_file() and p.suffix != ".exr"}


def test_glossy_study_writes_the_commands_bytes_whole_and_in_shards(study_folder, tmp_path):
    file = tmp_path / "tiny.toml"
    file.write_text(TINY_STUDY)
    whole = glossy.study(file, tmp_path / "whole")
    assert isinstance(whole, glossy.Study)
    # The command's run (the fixture) read the same study file text from another folder: same bytes but
    # for the path study.json records.
    ours, theirs = outputs(tmp_path / "whole"), outputs(study_folder)
    assert ours.keys() == theirs.keys()
    for name in ours:
        if name != "study.json":
            assert ours[name] == theirs[name], name
    assert whole.results == glossy.read_study(study_folder).results
    assert glossy.study(file, tmp_path / "sharded", shard="0/2") is None
    with pytest.raises(RuntimeError, match="not every sheet is complete"):
        glossy.study(file, tmp_path / "sharded", analyse=True)
    assert glossy.study(file, tmp_path / "sharded", shard="1/2") is None
    sharded = glossy.study(file, tmp_path / "sharded", analyse=True)
    assert outputs(tmp_path / "sharded") == ours
    assert sharded.results == whole.results
    # Run again: every sheet is complete, nothing is rendered, the same analysis is written.
    again = glossy.study(file, tmp_path / "whole", threads=1)
    assert outputs(tmp_path / "whole") == ours and again.summary == whole.summary


def test_glossy_study_refuses_bad_input_before_any_work_naming_the_keyword(tmp_path):
    file = tmp_path / "tiny.toml"
    file.write_text(TINY_STUDY)
    for kwargs, message in [({"threads": -1}, r"^threads: must be a whole number in \[0, "),
                            ({"threads": 1.5}, r"^threads: must be a whole number"),
                            ({"shard": "3/2"}, r"^shard: '3/2' is not i/N"),
                            ({"shard": "0/2", "analyse": True}, r"^analyse: analyses the whole study, not a shard"),
                            ({"merl_dir": tmp_path / "absent"}, r"absent")]:
        with pytest.raises(glossy.InputError, match=message):
            glossy.study(file, tmp_path / "out", **kwargs)
        assert not (tmp_path / "out").exists(), kwargs
    (tmp_path / "bad.toml").write_text(TINY_STUDY.replace("spp = 16", "spp = -1"))
    with pytest.raises(glossy.InputError, match=r"bad\.toml:\d+: settings\.spp"):
        glossy.study(tmp_path / "bad.toml", tmp_path / "out")
    assert not (tmp_path / "out").exists()
    (tmp_path / "mine").mkdir()
    (tmp_path / "mine" / "notes.txt").write_text("the user's")
    with pytest.raises(glossy.InputError, match=r"mine"):
        glossy.study(file, tmp_path / "mine")
    assert [p.name for p in (tmp_path / "mine").iterdir()] == ["notes.txt"]


def test_ctrl_c_stops_a_study_and_a_second_call_resumes_it(tmp_path):
    import os
    import signal
    import threading
    import time
    file = tmp_path / "slow.toml"
    file.write_text(TINY_STUDY.replace("spp = 16", "spp = 4096").replace("width = 32\nheight = 32", "width = 64\nheight = 64"))
    timer = threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT))
    start = time.monotonic()
    timer.start()
    with pytest.raises(KeyboardInterrupt):
        glossy.study(file, tmp_path / "out")
    timer.join()
    scale = float(os.environ.get("GLOSSY_TEST_TIME_SCALE", "1"))
    assert time.monotonic() - start < 10 * scale  # the sheet in progress stopped at its next tile
    # What it left is a study folder of this study, no sheet half-written: the next call takes it up.
    assert (tmp_path / "out" / "study.json").is_file()
    assert not list((tmp_path / "out").rglob("*.tmp*"))
    # An edited study file is the same study (study_plan.h): its sheets of other settings render again.
    file.write_text(TINY_STUDY)
    resumed = glossy.study(file, tmp_path / "out")
    assert len(resumed.rows["material"]) == 12 and (resumed.rows["spp"] == 16).all()
