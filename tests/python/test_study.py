"""glossy.read_study: a study's output folder as the command wrote it, read back into arrays and dicts — every
row and column of rows.csv, results.json and the plan unchanged — and a folder that is not one refused in
one line naming the file."""
import csv
import json
import math

import numpy as np
import pytest

import glossy
from conftest import run_cli

TINY_STUDY = """materials = ["merl/gold-paint", "nielsen2015/bluebook"]

[lightings]
sky = { sky = true }
grey = { constant = [0.8, 0.8, 0.9] }

[scenes]
preview = { builtin = "preview" }

[settings]
width = 16
height = 16
spp = 16
seed = 7
threads = 2
panels = "measured,microfacet:E2,smooth:E2,cook-torrance:E2"

[analysis]
resamples = 200
"""


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


def test_the_docs_study_example_runs_and_agrees_with_the_results(study_folder, capsys):
    from conftest import SOURCE_DIR
    import re
    text = (SOURCE_DIR / "docs" / "python.md").read_text()
    blocks = re.findall(r"```python study\n(.*?)```", text, flags=re.S)
    assert len(blocks) == 1
    exec(compile(blocks[0].replace("out/study-merl100", str(study_folder)), "docs/python.md", "exec"), {})
    printed = capsys.readouterr().out.splitlines()
    results = json.loads((study_folder / "analysis" / "results.json").read_text())
    within = next(d for d in results["e2MinusE1"] if d["image"] == "rrmse")["withinMaterialSpearman"]
    assert printed[0].startswith(f"E2 - E1, within a material: {within['estimate']:.3f} ")
    for model, line in zip(results["models"], printed[1:], strict=True):
        assert line.split()[0] == model["label"].split()[0], line
        # The mean r* recomputed from the rows is the one results.json reports.
        assert line.endswith(f"mean r* {model['meanRrmse']['estimate']:.4f}"), line
