"""glossy.error and glossy.fit against `glossy error` and `glossy fit`: the same figures and parameters."""
import json
import re
import tomllib

import numpy as np
import pytest

import glossy
from conftest import cli_error, material_path, run_cli, shared


def test_error_equals_glossy_error():
    table_path = shared("merl", "alum-bronze.binary.xz")
    table = glossy.load_merl(table_path)
    material = glossy.load_material(material_path("alum-bronze"))
    cli = json.loads(run_cli("error", "--material", material_path("alum-bronze"), "--measured", table_path, "--json").stdout)
    assert [f["fit"] for f in cli["fits"]] == material.fits
    for f in cli["fits"]:
        brdf = material.brdf(f["fit"])
        for metric in ("E1", "E2"):
            assert glossy.error(brdf, table, metric) == pytest.approx(f[metric], rel=1e-12, abs=0)
    with pytest.raises(glossy.InputError, match="^metric: "):
        glossy.error(material.brdf("smooth:E2"), table, "E3")
    with pytest.raises(glossy.InputError, match="^table: expected measured data"):
        glossy.error(material.brdf("smooth:E2"), material.brdf("smooth:E2"))


def test_fit_equals_glossy_fit(tmp_path):
    table_path = shared("merl", "gold-paint.binary.xz")
    table = glossy.load_merl(table_path)
    fit = glossy.fit(table, model="cook-torrance", metric="E1", starts=1, max_iterations=15, threads=2)
    out = tmp_path / "gold-paint.toml"
    run_cli("fit", "--measured", table_path, "--model", "cook-torrance", "--metric", "E1", "--starts", 1,
            "--max-iterations", 15, "--threads", 1, "-o", out)
    cli = tomllib.loads(out.read_text())["fit"][0]
    assert (fit.model, fit.metric) == ("cook-torrance", "E1")
    assert fit.error == pytest.approx(cli["error"], rel=1e-12)
    for key, value in fit.params.items():
        np.testing.assert_allclose(value, cli[key], rtol=1e-12, err_msg=key)
    # The fitted BRDF is the model with those parameters, and its E is what fit reports.
    assert glossy.error(fit.brdf, table, "E1") == pytest.approx(fit.error, rel=1e-12)
    # Saving puts the fit into a parameter file that glossy reads back to the same BRDF.
    saved = tmp_path / "saved.toml"
    fit.save(saved)
    again = glossy.load_material(saved).brdf("cook-torrance:E1")
    L, V = glossy.uniforms(200, seed=9), np.array([0.3, 0.0, 0.9])
    np.testing.assert_allclose(again.eval(L, V), fit.brdf.eval(L, V), rtol=1e-12)


def test_fit_refuses_what_glossy_fit_refuses():
    table = glossy.load_merl(shared("merl", "blue-rubber.binary.xz"))
    with pytest.raises(glossy.InputError) as python_error:
        glossy.fit(table, model="measured")
    assert "measured" in str(python_error.value)
    with pytest.raises(glossy.InputError, match=r"^starts: must be a whole number in \[1, 64\], not '0'$"):
        glossy.fit(table, starts=0)
    assert "fit" in cli_error("fit", "--measured", shared("merl", "blue-rubber.binary.xz"), "--model", "measured",
                              "--metric", "E2")


def test_help_explains():
    assert "Levenberg-Marquardt" in glossy.fit.__doc__
    assert "glossy render" in glossy.render.__doc__ and "KeyboardInterrupt" in glossy.render.__doc__
    assert "(N, 3)" in glossy.Brdf.eval.__doc__


def test_save_is_glossy_fit_o(tmp_path, capsys):
    """Fit.save is `glossy fit -o`: the same file, the material named and measured after the data fitted, not
    after the output file; beside a published fit, which only replace=True removes."""
    table_path = shared("merl", "gold-paint.binary.xz")
    fit = glossy.fit(glossy.load_merl(table_path), model="cook-torrance", metric="E1", starts=1, max_iterations=15, threads=1)
    (tmp_path / "x").mkdir()
    saved = tmp_path / "x" / "gold-paint-myfit.toml"
    fit.save(saved)
    cli_out = tmp_path / "cli.toml"
    run_cli("fit", "--measured", table_path, "--model", "cook-torrance", "--metric", "E1", "--starts", 1,
            "--max-iterations", 15, "--threads", 1, "-o", cli_out)
    doc, cli = tomllib.loads(saved.read_text()), tomllib.loads(cli_out.read_text())
    assert (doc["name"], doc["measured"]) == ("gold-paint", "gold-paint.binary")
    assert {k: v for k, v in doc.items() if k != "fit"} == {k: v for k, v in cli.items() if k != "fit"}
    mine, theirs = doc["fit"][0], cli["fit"][0]
    assert mine["by"] == "glossy" and mine["data"] == "gold-paint.binary.xz"
    assert mine["database"] == "MERL (NBRDF reconstruction)"
    for key in ("model", "metric", "by", "data", "database", "date", "settings"):
        assert mine[key] == theirs[key], key
    assert glossy.load_material(saved).fits == ["cook-torrance:E1:glossy"]

    # The library's file with its published fits only (it holds glossy's refits too).
    library = tmp_path / "gold-paint.toml"
    text = material_path("gold-paint").read_text()
    library.write_text("".join(b for b in re.split(r"(?m)^(?=\[\[fit\]\])", text) if 'by = "glossy"' not in b))
    published = tomllib.loads(library.read_text())["fit"]
    assert published and all("by" not in f for f in published)
    fit.save(library)
    fits = tomllib.loads(library.read_text())["fit"]
    assert all(f in fits for f in published)
    assert len(fits) == len(published) + 1
    assert "the published cook-torrance:E1 fit stays beside it" in capsys.readouterr().err
    fit.save(library)
    assert "replaces glossy's earlier cook-torrance:E1:glossy fit" in capsys.readouterr().err
    fit.save(library, replace=True)
    assert "removes the published cook-torrance:E1 fit" in capsys.readouterr().err
    assert "cook-torrance:E1" not in glossy.load_material(library).fits
    with pytest.raises(glossy.InputError, match="^path "):
        fit.save(tmp_path / "no-such-folder" / "x.toml")
