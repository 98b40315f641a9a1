"""glossy.merge_fits, glossy.merge_sheets, glossy.plot and glossy.report write what `glossy merge fits`,
`glossy merge sheets`, `glossy plot` and `glossy report` write (renderer/app/merge_job.h, plot_job.h,
report_job.h), and glossy.fit_tables what `glossy fit --measured-dir` writes (fit_job.h), byte for byte,
and refuse what they refuse in the keywords' names; glossy.list_library returns what `glossy list` prints
(list_job.h)."""
import shutil

import pytest

import glossy
from conftest import cli_error, material_path, run_cli


def test_merge_sheets_is_the_cli_merge(tmp_path):
    sheets = tmp_path / "sheets"
    sheets.mkdir()
    for name in ("alum-bronze", "chrome"):
        run_cli("sheet", "--material", material_path(name), "--width", 16, "--height", 16, "--spp", 4, "--threads", 2,
                "-o", sheets / f"{name}.exr")
    assert glossy.merge_sheets(sheets, csv=tmp_path / "py.csv", json=tmp_path / "py.json") == 2
    run_cli("merge", "sheets", sheets, "--csv", tmp_path / "cli.csv", "--json", tmp_path / "cli.json")
    assert (tmp_path / "py.csv").read_bytes() == (tmp_path / "cli.csv").read_bytes()
    assert (tmp_path / "py.json").read_bytes() == (tmp_path / "cli.json").read_bytes()
    assert "delta_e_itp" in (tmp_path / "py.csv").read_text().splitlines()[0]
    with pytest.raises(glossy.InputError, match=r"^glossy merge sheets needs csv FILE, json FILE or both$"):
        glossy.merge_sheets(sheets)
    with pytest.raises(glossy.InputError) as error:
        glossy.merge_sheets(sheets, csv=tmp_path / "table.txt")
    assert str(error.value).replace("csv", "--csv", 1) == cli_error("merge", "sheets", sheets, "--csv", tmp_path / "table.txt")


def test_merge_fits_is_the_cli_merge(tmp_path):
    shards = tmp_path / "shards"
    shards.mkdir()
    for name in ("alum-bronze", "gold-paint"):
        shutil.copy(material_path(name), shards / f"{name}.toml")
    done = glossy.merge_fits(shards, tmp_path / "py")
    assert done["materials"] == 2 and done["files_written"] == 2 and done["replaced"] == 0
    run_cli("merge", "fits", shards, "-o", tmp_path / "cli")
    for name in ("alum-bronze", "gold-paint"):
        assert (tmp_path / "py" / f"{name}.toml").read_bytes() == (tmp_path / "cli" / f"{name}.toml").read_bytes()
    # Merged again: every fit is already there, nothing is written.
    assert glossy.merge_fits(shards, tmp_path / "py")["files_written"] == 0
    with pytest.raises(glossy.InputError, match=r"not a directory"):
        glossy.merge_fits(tmp_path / "none", tmp_path / "py")


def test_report_is_the_cli_report(tmp_path):
    sheets = tmp_path / "sheets"
    sheets.mkdir()
    run_cli("sheet", "--material", material_path("alum-bronze"), "--width", 16, "--height", 16, "--spp", 4, "--threads", 2,
            "-o", sheets / "alum-bronze.exr")
    done = glossy.report(sheets, tmp_path / "py")
    assert done["sheets"] == 1 and done["materials"] == 1 and done["images"] > 0
    run_cli("report", sheets, "-o", tmp_path / "cli")
    py_files = sorted(p.relative_to(tmp_path / "py") for p in (tmp_path / "py").rglob("*") if p.is_file())
    cli_files = sorted(p.relative_to(tmp_path / "cli") for p in (tmp_path / "cli").rglob("*") if p.is_file())
    assert py_files == cli_files
    for f in py_files:
        assert (tmp_path / "py" / f).read_bytes() == (tmp_path / "cli" / f).read_bytes(), f
    with pytest.raises(glossy.InputError, match=r"^plot_kinds: 'lobes' is none of theta_h, image_slice, albedo, polar$"):
        glossy.report(sheets, tmp_path / "py", plot_kinds=["lobes"])
    with pytest.raises(glossy.InputError, match=r"^output .*alum-bronze\.exr: exists and is not a folder$"):
        glossy.report(sheets, sheets / "alum-bronze.exr")


def test_plot_is_the_cli_plot(tmp_path):
    args = dict(figures=["theta_h", "albedo"], decades=6, polar_scale="linear")
    assert glossy.plot(material_path("gold-paint"), tmp_path / "py", **args) == 2
    run_cli("plot", "--material", material_path("gold-paint"), "-o", tmp_path / "cli", "--figures", "theta_h,albedo",
            "--decades", 6, "--polar-scale", "linear")
    py_files = sorted(p.relative_to(tmp_path / "py") for p in (tmp_path / "py").rglob("*") if p.is_file())
    assert py_files == sorted(p.relative_to(tmp_path / "cli") for p in (tmp_path / "cli").rglob("*") if p.is_file())
    for f in py_files:
        assert (tmp_path / "py" / f).read_bytes() == (tmp_path / "cli" / f).read_bytes(), f
    with pytest.raises(glossy.InputError, match=r"^channel: 'Y' is none of R, G, B, luminance$"):
        glossy.plot(material_path("gold-paint"), tmp_path / "py", channel="Y")
    with pytest.raises(glossy.InputError, match=r"^figures: 'lobes' is none of theta_h, image_slice, albedo, polar$"):
        glossy.plot(material_path("gold-paint"), tmp_path / "py", figures=["lobes"])
    with pytest.raises(glossy.InputError, match=r"^figures: a list, not one string$"):
        glossy.plot(material_path("gold-paint"), tmp_path / "py", figures="theta_h")
    with pytest.raises(glossy.InputError, match=r"^figures: each must be a string$"):
        glossy.plot(material_path("gold-paint"), tmp_path / "py", figures=["theta_h", 2])
    with pytest.raises(glossy.InputError, match=r"^decades: must be 1 to 20"):
        glossy.plot(material_path("gold-paint"), tmp_path / "py", decades=21)


def test_list_library_is_what_glossy_list_prints(tmp_path):
    rows = glossy.list_library()
    printed = run_cli("list").stdout
    listed = [r for r in rows if r["error"] is None]
    assert f"\n{len(listed)} materials," in printed
    chrome = next(r for r in rows if r["material"] == "chrome")
    assert chrome["database"].startswith("MERL")
    line = next(l for l in printed.splitlines() if l.startswith("chrome "))
    assert f"{chrome['albedo']['cook-torrance:E2']:.4f}" in line and chrome["measured"] in line
    folder = tmp_path / "lib"
    folder.mkdir()
    shutil.copy(material_path("chrome"), folder / "chrome.toml")
    (folder / "bad.toml").write_text("garbage = [\n")
    rows = glossy.list_library([folder], panels="ward:Ngan05")
    assert [r["error"] is not None for r in rows] == [True, False] and list(rows[1]["albedo"]) == ["ward:Ngan05"]
    with pytest.raises(glossy.InputError, match=r"^panels: "):
        glossy.list_library(panels="nonsense:E9")


def test_fit_tables_is_the_cli_batch(tmp_path):
    tables = tmp_path / "tables"
    tables.mkdir()
    shutil.copy(material_path("gold-paint").with_suffix(".nbrdf"), tables / "gold-paint.nbrdf")
    settings = dict(starts=1, max_iterations=3)
    done = glossy.fit_tables(tables, tmp_path / "py", models=["ashikhmin-shirley"], metrics=["E2"], **settings)
    assert done == {"tables": 1, "fits": 1, "already_done": 0}
    run_cli("fit", "--measured-dir", tables, "--out-dir", tmp_path / "cli", "--model", "ashikhmin-shirley", "--metric", "E2",
            "--starts", 1, "--max-iterations", 3)
    assert (tmp_path / "py" / "gold-paint.toml").read_bytes() == (tmp_path / "cli" / "gold-paint.toml").read_bytes()
    # Again: the fit is there, made with these settings; nothing is fitted.
    assert glossy.fit_tables(tables, tmp_path / "py", models=["ashikhmin-shirley"], metrics=["E2"], **settings)["already_done"] == 1
    with pytest.raises(glossy.InputError, match=r"^metrics"):
        glossy.fit_tables(tables, tmp_path / "py", metrics=["E3"], **settings)
    with pytest.raises(glossy.InputError, match=r"^models"):
        glossy.fit_tables(tables, tmp_path / "py", models=["nonsense"], **settings)
