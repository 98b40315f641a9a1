"""glossy.Brdf against the command line: eval and pdf on ../shared/testvectors equal `glossy eval` to
1e-12, samples equal `glossy sample` draw for draw, and bad input raises InputError with its message."""
import csv
import warnings
from collections import defaultdict

import numpy as np
import pytest

import glossy
from conftest import cli_error, material_path, run_cli, shared


def cli_rows(text):
    return np.array([[float(x) for x in line.split(",")] for line in text.strip().splitlines()])


def vector_groups():
    groups = defaultdict(list)
    with open(shared("testvectors", "brdf_eval.csv")) as f:
        for row in csv.DictReader(f):
            groups[(row["material"], row["fit"])].append(row)
    return groups


def brdf_and_options(material, fit):
    if fit == "measured":
        path = shared("merl", "blue-rubber.binary.xz")
        return glossy.load_merl(path), ["--measured", path]
    return glossy.load_material(material_path(material)).brdf(fit), ["--material", material_path(material), "--fit", fit]


def test_eval_and_pdf_equal_the_cli_on_the_test_vectors():
    groups = vector_groups()
    assert len(groups) >= 24
    for (material, fit), rows in groups.items():
        brdf, options = brdf_and_options(material, fit)
        L = np.array([[float(r[k]) for k in ("Lx", "Ly", "Lz")] for r in rows])
        V = np.array([[float(r[k]) for k in ("Vx", "Vy", "Vz")] for r in rows])
        stdin = "".join(",".join(r[k] for k in ("Lx", "Ly", "Lz", "Vx", "Vy", "Vz")) + "\n" for r in rows)
        cli = cli_rows(run_cli("eval", "--pdf", *options, stdin=stdin).stdout)
        rho, pdf = brdf.eval(L, V), brdf.pdf(L, V)
        np.testing.assert_allclose(rho, cli[:, :3], rtol=1e-12, atol=0, err_msg=f"{material} {fit}")
        np.testing.assert_allclose(pdf, cli[:, 3], rtol=1e-12, atol=0, err_msg=f"{material} {fit}")
        # And the independent values, as tests/testvectors_test.cpp holds the library to them.
        expected = np.array([[float(r[k]) for k in ("R", "G", "B")] for r in rows])
        if fit == "measured":
            assert np.mean(rho == expected) > 0.99, f"{material} {fit}"
        else:
            np.testing.assert_allclose(rho, expected, rtol=1e-5, atol=1e-12, err_msg=f"{material} {fit}")


@pytest.mark.parametrize("fit", ["cook-torrance:E2", "smooth:E2", "ashikhmin-shirley:E1", "microfacet:E2", "measured"])
def test_samples_equal_the_cli_draw_for_draw(fit):
    brdf, options = brdf_and_options("alum-bronze", fit)
    wo = (0.3, -0.2, 0.8)
    cli = cli_rows(run_cli("sample", *options, "--wo", ",".join(map(str, wo)), "-n", 3000, "--seed", 11).stdout)
    L, pdf, weight = brdf.sample(np.array(wo), glossy.uniforms(3000, seed=11))
    np.testing.assert_allclose(L, cli[:, 0:3], rtol=1e-12, atol=0)
    np.testing.assert_allclose(pdf, cli[:, 3], rtol=1e-12, atol=0)
    np.testing.assert_allclose(weight, cli[:, 4:7], rtol=1e-12, atol=0)
    assert (pdf > 0).mean() > 0.5  # the comparison is over real samples, not zeros
    # The sampler's density is the one pdf() reports.
    valid = pdf > 0
    np.testing.assert_allclose(brdf.pdf(L[valid], np.array(wo)), pdf[valid], rtol=1e-9)


def test_a_single_direction_stands_for_every_row_and_shapes_are_checked():
    brdf = glossy.load_material(material_path("alum-bronze")).brdf("cook-torrance:E2")
    rng = np.random.default_rng(1)
    L = rng.normal(size=(100, 3))
    L[:, 2] = np.abs(L[:, 2])
    V = np.array([0.1, 0.2, 0.9])
    np.testing.assert_array_equal(brdf.eval(L, V), brdf.eval(L, np.tile(V, (100, 1))))
    assert brdf.eval(V, V).shape == (1, 3)
    with pytest.raises(glossy.InputError, match=r"^L and V: 100 and 7 rows"):
        brdf.eval(L, np.tile(V, (7, 1)))
    with pytest.raises(glossy.InputError, match=r"^L: expected shape \(N, 3\) or \(3,\), got \(100, 2\)$"):
        brdf.eval(L[:, :2], V)
    with pytest.raises(glossy.InputError, match=r"^u: expected shape \(N, 3\)"):
        brdf.sample(V, np.zeros((4, 2)))
    # Other dtypes and layouts are converted, with the same values.
    np.testing.assert_array_equal(brdf.eval(L.astype(np.float32), V), brdf.eval(L.astype(np.float32).astype(np.float64), V))
    np.testing.assert_array_equal(brdf.eval(np.asfortranarray(L), V), brdf.eval(L, V))


def test_bad_directions_and_numbers_name_their_row():
    brdf = glossy.load_material(material_path("alum-bronze")).brdf("smooth:E2")
    L = np.tile([0.0, 0.0, 1.0], (5, 1))
    L[3] = [np.nan, 0.0, 1.0]
    L[4] = 0.0
    with pytest.raises(glossy.InputError, match=r"^L\[3\]: a direction is zero or not finite$"):
        brdf.eval(L, [0, 0, 1])
    with pytest.raises(glossy.InputError, match=r"^V\[0\]: a direction is zero or not finite$"):
        brdf.pdf([0, 0, 1], [0, 0, 0])
    u = glossy.uniforms(10, seed=1)
    u[6, 1] = 1.0
    with pytest.raises(glossy.InputError, match=r"^u\[6\]: the numbers must lie in \[0, 1\)$"):
        brdf.sample([0, 0, 1], u)
    # The command line says the same of the same row.
    assert cli_error("eval", "--material", material_path("alum-bronze"), "--fit", "smooth:E2",
                     stdin="0,0,1,0,0,1\n0,0,0,0,0,1\n") == "stdin line 2: a direction is zero or not finite"


def test_out_is_written_in_place_without_a_copy():
    brdf = glossy.load_material(material_path("alum-bronze")).brdf("ashikhmin-shirley:E2")
    L = glossy.uniforms(1000, seed=3)
    V = np.array([0.0, 0.6, 0.8])
    out = np.empty((1000, 3))
    result = brdf.eval(L, V, out=out)
    assert result is out or np.shares_memory(result, out)
    np.testing.assert_array_equal(out, brdf.eval(L, V))
    dens = np.empty(1000)
    assert np.shares_memory(brdf.pdf(L, V, out=dens), dens)
    with pytest.raises(glossy.InputError, match=r"^out: must be a writable C-contiguous float64 array of shape \(1000, 3\)$"):
        brdf.eval(L, V, out=np.empty((1000, 3), dtype=np.float32))
    with pytest.raises(glossy.InputError, match=r"^out:"):
        brdf.eval(L, V, out=np.empty((3, 1000)).T)


def test_threads_do_not_change_a_value():
    brdf = glossy.load_material(material_path("gold-paint")).brdf("microfacet:E2")
    rng = np.random.default_rng(5)
    L, V = rng.normal(size=(300_000, 3)), rng.normal(size=(300_000, 3))
    L[:, 2], V[:, 2] = np.abs(L[:, 2]), np.abs(V[:, 2])
    np.testing.assert_array_equal(brdf.eval(L, V, threads=1), brdf.eval(L, V))
    np.testing.assert_array_equal(brdf.pdf(L, V, threads=1), brdf.pdf(L, V, threads=2))
    u = glossy.uniforms(300_000, seed=2)
    for a, b in zip(brdf.sample(V, u, threads=1), brdf.sample(V, u)):
        np.testing.assert_array_equal(a, b)


def test_make_brdf_is_a_fit_by_its_parameters():
    material = glossy.load_material(material_path("alum-bronze"))
    fitted = material.brdf("cook-torrance:E2")
    made = glossy.make_brdf("cook-torrance", **material.params("cook-torrance:E2"))
    assert made.model == "cook-torrance" and made.params == fitted.params
    L, V = glossy.uniforms(500, seed=4), np.array([0.2, 0.1, 0.95])
    np.testing.assert_array_equal(made.eval(L, V), fitted.eval(L, V))
    assert "cook-torrance" in glossy.models()
    with pytest.raises(glossy.InputError, match=r"^make_brdf: unknown model .nonsense. \(known: "):
        glossy.make_brdf("nonsense")
    params = material.params("cook-torrance:E2")
    params["m"] = float("nan")
    with pytest.raises(glossy.InputError, match="make_brdf: cook-torrance"):
        glossy.make_brdf("cook-torrance", **params)


def test_file_errors_carry_the_cli_message(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('name = "bad"\n[[fit]]\nmodel = "cook-torrance"\nmetric = "E2"\nkd = [0.1, 0.1]\n')
    with pytest.raises(glossy.InputError) as python_error:
        glossy.load_material(bad)
    assert str(python_error.value) == cli_error("eval", "--material", bad, "--fit", "cook-torrance:E2", stdin="")
    with pytest.raises(glossy.InputError) as python_error:
        glossy.load_material(material_path("alum-bronze")).brdf("cook-torrance:E3")
    assert str(python_error.value) == "fit: " + cli_error("eval", "--material", material_path("alum-bronze"),
                                                          "--fit", "cook-torrance:E3", stdin="").split(": ", 1)[1]
    missing = tmp_path / "nothing.binary"
    with pytest.raises(glossy.InputError) as python_error:
        glossy.load_merl(missing)
    assert str(python_error.value) == cli_error("render", "--measured", missing, "-o", tmp_path / "x.exr")
    truncated = tmp_path / "short.binary"
    truncated.write_bytes(b"\x5a\x00\x00\x00" * 3 + b"\x00" * 100)
    with pytest.raises(glossy.InputError) as python_error:
        glossy.load_merl(truncated)
    assert str(python_error.value) == cli_error("eval", "--measured", truncated, stdin="")
    assert isinstance(python_error.value, ValueError)


def test_measured_data_knows_its_source_and_notes_become_warnings(tmp_path):
    table = glossy.load_merl(shared("merl", "blue-rubber.binary.xz"))
    assert isinstance(table, glossy.MeasuredBrdf) and isinstance(table, glossy.Brdf)
    assert table.model == "measured" and table.params == {}
    assert table.label.startswith("MERL (NBRDF reconstruction) ")
    # A table with two unmeasured bins: the note glossy prints on stderr is a GlossyWarning here.
    values = np.full(3 * 90 * 90 * 180, 150.0)
    values[[10, 3 * 90 * 90 * 180 - 1]] = -1.0
    path = tmp_path / "holes.binary"
    path.write_bytes(np.array([90, 90, 180], dtype="<i4").tobytes() + values.astype("<f8").tobytes())
    with pytest.warns(glossy.GlossyWarning) as caught:
        holes = glossy.load_merl(path)
    assert holes.invalid_bins == 2
    assert [str(w.message) for w in caught] == [f"{path}: 2 of 1458000 bins unmeasured (they evaluate to 0)"]
    cli = run_cli("eval", "--measured", path, stdin="0,0,1,0,0,1\n")
    assert cli.stderr == f"glossy: {path}: 2 of 1458000 bins unmeasured (they evaluate to 0)\n"


def test_input_errors_are_one_safe_line(tmp_path):
    """InputError's message is the command line's one safe line: control characters from a file name or a
    file's content come escaped, and a long echo is cut with its length (materials/core/text.h, safeLine)."""
    evil = tmp_path / "evil\x1b[2J\nsecond\x07.toml"
    with pytest.raises(glossy.InputError) as e:
        glossy.load_material(evil)
    message = str(e.value)
    assert not any(ord(c) < 0x20 or ord(c) == 0x7f for c in message), repr(message)
    assert "evil\\x1b[2J\\nsecond\\x07.toml" in message
    assert message == cli_error("eval", "--material", evil, "--fit", "smooth:E2")

    bad = tmp_path / "m.toml"
    bad.write_text('name = "a\\u0000\\u001b[1A\\u202e' + "b" * 5000 + '"\n')
    with pytest.raises(glossy.InputError) as e:
        glossy.load_material(bad)
    message = str(e.value)
    assert not any(ord(c) < 0x20 or ord(c) == 0x7f or c == "\u202e" for c in message), repr(message)
    assert len(message) < 1200, message

    long = tmp_path / ("x" * 200) / ("y" * 200) / ("z" * 200) / ("w" * 200) / ("v" * 200) / "m.toml"
    with pytest.raises(glossy.InputError) as e:
        glossy.load_material(long)
    message = str(e.value)
    assert "characters) …" in message and len(message) < 1200, message
    assert message.endswith("cannot open material file: not found"), message
