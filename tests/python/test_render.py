"""glossy.render and glossy.sheet: the images of `glossy render` and `glossy sheet`, bit for bit, with a
progress callback, Ctrl-C, the GIL released while they work, and the command line's messages."""
import json
import os
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

import glossy
from conftest import cli_error, material_path, run_cli, shared

# Instrumented builds run several times slower (tests/CMakeLists.txt sets this for the sanitized one): the
# limits below are "far less than the whole render", not timings.
TIME_SCALE = float(os.environ.get("GLOSSY_TEST_TIME_SCALE", "1"))

SMALL = dict(size=(40, 24), spp=4, seed=3, threads=2)


def cli_render(tmp_path, *options):
    out = tmp_path / "cli.exr"
    run_cli("render", "--width", 40, "--height", 24, "--spp", 4, "--seed", 3, "--threads", 2, *options, "-o", out)
    return glossy.read_exr(out)


def test_render_is_the_cli_image_bit_for_bit(tmp_path):
    image = glossy.render(**SMALL)
    assert image.dtype == np.float32 and image.shape == (24, 40, 3)
    assert image.mean() > 0
    np.testing.assert_array_equal(image, cli_render(tmp_path))

    material = glossy.load_material(material_path("alum-bronze"))
    image = glossy.render(material=material, fit="cook-torrance:E2", env_constant=(0.5, 0.7, 1.0), **SMALL)
    np.testing.assert_array_equal(image, cli_render(tmp_path, "--material", material_path("alum-bronze"),
                                                   "--fit", "cook-torrance:E2", "--env-constant", "0.5,0.7,1"))
    # Any Brdf renders as the fit it came from.
    np.testing.assert_array_equal(glossy.render(brdf=material.brdf("cook-torrance:E2"), env_constant=(0.5, 0.7, 1.0), **SMALL),
                                  image)

    merl = shared("merl", "blue-rubber.binary.xz")
    image = glossy.render(measured=merl, env_rotate=30, **SMALL)
    np.testing.assert_array_equal(image, cli_render(tmp_path, "--measured", merl, "--env-rotate", 30))


def test_render_writes_the_exr_the_cli_writes(tmp_path):
    out = tmp_path / "sub" / "py.exr"
    image = glossy.render(output=out, **SMALL)
    np.testing.assert_array_equal(glossy.read_exr(out), image)


def test_progress_counts_the_tiles():
    calls = []
    glossy.render(size=(100, 70), spp=64, threads=2, progress=lambda done, total: calls.append((done, total)))
    tiles = 7 * 5  # 16-pixel tiles
    assert calls and calls[-1] == (tiles, tiles)
    assert all(total == tiles for _, total in calls)
    assert [d for d, _ in calls] == sorted({d for d, _ in calls})


def test_an_exception_in_progress_stops_the_render():
    class Stop(Exception):
        pass

    def stop(done, total):
        raise Stop

    start = time.monotonic()
    with pytest.raises(Stop):
        glossy.render(size=(512, 512), spp=4096, threads=2, progress=stop)
    assert time.monotonic() - start < 10 * TIME_SCALE


def test_ctrl_c_interrupts_a_render_and_a_sheet():
    for call in (lambda: glossy.render(size=(512, 512), spp=4096, threads=2),
                 lambda: glossy.sheet(material=material_path("alum-bronze"), size=256, spp=4096, threads=2)):
        timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
        start = time.monotonic()
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            call()
        timer.join()
        # Far less than the render would take: it stopped at the next tile.
        assert time.monotonic() - start < 10 * TIME_SCALE


def test_the_gil_is_released_while_rendering():
    ticks = 0
    running = True

    def count():
        nonlocal ticks
        while running:
            ticks += 1
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    start = time.monotonic()
    glossy.render(size=(160, 160), spp=64, threads=1)
    elapsed = time.monotonic() - start
    running = False
    counter.join()
    # The counter sleeps 1 ms per tick: with the GIL held by the render it would not have run at all.
    assert elapsed > 0.2 and ticks > 0.3 * elapsed / 0.001


def test_bad_arguments_raise_the_cli_messages(tmp_path):
    with pytest.raises(glossy.InputError) as python_error:
        glossy.render(scene=tmp_path / "none.gltf", **SMALL)
    assert str(python_error.value) == cli_error("render", "--scene", tmp_path / "none.gltf", "-o", tmp_path / "x.exr")
    with pytest.raises(glossy.InputError) as python_error:
        glossy.render(env_constant=-1, **SMALL)
    assert str(python_error.value) == cli_error("render", "--env-constant", "-1", "-o", tmp_path / "x.exr")
    with pytest.raises(glossy.InputError) as python_error:
        glossy.render(size=(30000, 30000), spp=1)
    assert "--width" in str(python_error.value)
    with pytest.raises(glossy.InputError, match=r"^spp: must be a whole number in \[1, 2147483647\], not '0'$"):
        glossy.render(spp=0)
    with pytest.raises(glossy.InputError, match=r"^material and fit: give both"):
        glossy.render(material=material_path("alum-bronze"))
    with pytest.raises(TypeError, match=r"^render\(\) got an unexpected keyword argument 'sizes'$"):
        glossy.render(sizes=(10, 10))
    with pytest.raises(glossy.InputError, match=r"^spp: must be a whole number$"):
        glossy.render(spp=1.5)
    with pytest.raises(glossy.InputError, match=r"^size: must be a whole number$"):
        glossy.render(size=10**30)
    with pytest.raises(glossy.InputError, match=r"^env_constant: expected a radiance or \(R, G, B\)$"):
        glossy.render(env_constant="bright")
    with pytest.raises(glossy.InputError, match=r"^brdf_sampling: must be 'lobe' or 'cosine'"):
        glossy.render(brdf_sampling="uniform")
    with pytest.raises(glossy.InputError) as python_error:
        glossy.render(output=tmp_path / "x.png", **SMALL)
    assert str(python_error.value).replace("output", "-o") == cli_error("render", "-o", tmp_path / "x.png")


def test_sheet_is_the_cli_sheet(tmp_path):
    merl = shared("merl", "alum-bronze.binary.xz")
    args = dict(material=material_path("alum-bronze"), measured=merl, size=32, spp=8, seed=5, threads=2)
    sheet = glossy.sheet(**args)
    out = tmp_path / "cli.exr"
    printed = run_cli("sheet", "--material", material_path("alum-bronze"), "--measured", merl, "--width", 32, "--height", 32,
                      "--spp", 8, "--seed", 5, "--threads", 2, "-o", out).stdout
    assert sheet.table == printed
    np.testing.assert_array_equal(sheet.image, glossy.read_exr(out))
    assert list(sheet.panels) == ["measured", "microfacet_E2", "smooth_E2", "ashikhmin_shirley_E1", "ashikhmin_shirley_E2",
                                  "cook_torrance_E1", "cook_torrance_E2"]
    for layer, panel in sheet.panels.items():
        assert panel.shape == (32, 32, 3) and np.shares_memory(panel, sheet.image)
        np.testing.assert_array_equal(panel, glossy.read_exr(out, layer)[:, list(sheet.panels).index(layer) * 32:][:, :32])
    assert not sheet.image.flags.writeable
    ct = sheet.figures["cook_torrance_E2"]
    assert ct["label"] == "CT E2" and ct["fit"] == "cook-torrance:E2" and ct["E2"] > 0
    lo, hi = ct["relative_rmse_ci"]
    assert lo <= ct["relative_rmse"] <= hi
    assert sheet.figures["measured"]["relative_rmse"] is None
    assert set(sheet.maps["cook_torrance_E2"]) == {"reldiff", "flip"} and sheet.maps["cook_torrance_E2"]["flip"].shape == (32, 32)
    assert sheet.spp == 8 and sheet.verdict
    # The noise-floor row and the warnings, as the EXR has them (glossy:noiseFloor.*, glossy:warnings).
    floor = sheet.noise_floor
    assert floor["label"] == "noise floor" and floor["relative_rmse_noisy"] > 0
    assert floor["relative_rmse_ci"][0] <= floor["relative_rmse"] <= floor["relative_rmse_ci"][1]
    assert floor["flip"] < ct["flip"]
    for key in ("delta_e_itp", "ssim"):
        assert ct[f"{key}_ci"][0] <= ct[key] <= ct[f"{key}_ci"][1]
    # The display figures from the maps glossy.delta_e_itp and glossy.ssim give, over the object (where the
    # relative difference is not 0): the sheet's own. sheet.panels are the mean images the figures compare.
    obj = sheet.maps["cook_torrance_E2"]["reldiff"] != 0
    measured, model = sheet.panels["measured"], sheet.panels["cook_torrance_E2"]
    assert np.isclose(glossy.delta_e_itp(measured, model)[obj].mean(dtype=np.float64), ct["delta_e_itp"], rtol=1e-5)
    assert np.isclose(glossy.ssim(measured, model)[obj].mean(dtype=np.float64), ct["ssim"], rtol=1e-5)
    # At 8 spp noise alone is as far as the model (the sheet warns): only that the row has the figures.
    assert floor["delta_e_itp"] > 0 and 0 < floor["ssim"] < 1
    assert sheet.warnings and all("intervals may be too narrow" in w for w in sheet.warnings)
    assert not sheet.verdict.startswith("closest: ")
    assert "noise floor" in sheet.table
    saved = tmp_path / "py.exr"
    sheet.save(saved)
    assert saved.with_suffix(".png").exists()
    for layer in ["", "measured", "smooth_E2"]:
        np.testing.assert_array_equal(glossy.read_exr(saved, layer), glossy.read_exr(out, layer))


def test_sheet_progress_and_bad_input(tmp_path):
    calls = []
    glossy.sheet(material=material_path("alum-bronze"), size=16, spp=4, threads=2, progress=lambda d, t: calls.append((d, t)))
    assert calls[-1][0] == calls[-1][1] > 0
    with pytest.raises(glossy.InputError) as python_error:
        glossy.sheet(material=tmp_path / "none.toml")
    assert str(python_error.value) == cli_error("sheet", "--material", tmp_path / "none.toml", "-o", tmp_path / "x.exr")
    with pytest.raises(glossy.InputError, match=r"^size: width: must be a whole number in \[8, 16384\], not '4'$"):
        glossy.sheet(material=material_path("alum-bronze"), size=4)


def test_sheet_panels_are_the_cli_panels_and_the_grid_is_the_sheets(tmp_path):
    args = dict(material=material_path("chrome"), size=16, spp=4, seed=2, threads=2)
    sheet = glossy.sheet(panels="microfacet:E2,cook-torrance:E1", **args)
    assert list(sheet.panels) == ["microfacet_E2", "cook_torrance_E1"]
    assert [f["label"] for f in sheet.figures.values()] == ["Microfacet E2", "CT E1"]
    out = tmp_path / "cli.exr"
    run_cli("sheet", "--material", material_path("chrome"), "--width", 16, "--height", 16, "--spp", 4, "--seed", 2,
            "--threads", 2, "--panels", "microfacet:E2,cook-torrance:E1", "-o", out)
    np.testing.assert_array_equal(sheet.image, glossy.read_exr(out))
    for bad in ["bogus:E2", "smooth:E2,smooth:E2", ""]:
        with pytest.raises(glossy.InputError) as python_error:
            glossy.sheet(panels=bad, **args)
        assert str(python_error.value).replace("panels", "--panels", 1) == cli_error(
            "sheet", "--material", material_path("chrome"), "--panels", bad, "-o", tmp_path / "x.exr")
    # The table the default sheet is made of: its layers, labels and colours, measured first.
    grid = glossy.comparison_grid()
    default = [row for row in grid if row["default"]]
    assert [row["layer"] for row in default] == list(glossy.sheet(**args).panels)
    assert [row["colour"] for row in default][:2] == ["#000000", "#e69f00"]
    assert {"fit", "layer", "label", "colour", "default"} == set(grid[0])
    assert any(row["fit"] == "smooth:E1" and not row["default"] for row in grid)
    # The command gives scripts the same table, row for row.
    assert json.loads(run_cli("list", "--grid").stdout) == grid


def test_read_exr_refuses_a_fifo_at_once(tmp_path):
    fifo = tmp_path / "pipe.exr"
    os.mkfifo(fifo)
    # A reader that opened the FIFO would wait for a writer (holding the GIL): another process writes to it
    # after a few seconds, so that such a reader fails this test instead of hanging it.
    writer = subprocess.Popen(["sh", "-c", 'sleep 5; while :; do : >"$0"; sleep 0.02; done', str(fifo)])
    start = time.monotonic()
    try:
        with pytest.raises(glossy.InputError, match=r"pipe\.exr: is a FIFO"):
            glossy.read_exr(fifo)
    finally:
        writer.kill()
        writer.wait()
    assert time.monotonic() - start < 5


def test_display_figures_of_any_two_images():
    rng = np.random.default_rng(3)
    a = rng.uniform(0, 1.5, (20, 30, 3)).astype(np.float32)
    assert glossy.delta_e_itp(a, a).shape == (20, 30) and not glossy.delta_e_itp(a, a).any()
    np.testing.assert_allclose(glossy.ssim(a, a), 1.0, atol=1e-6)
    # Brighter is farther, on a brighter display too; what the display clips is no difference.
    assert glossy.delta_e_itp(a, 1.2 * a, white=400).mean() > glossy.delta_e_itp(a, 1.2 * a).mean() > 0
    assert not glossy.delta_e_itp(np.full((4, 4, 3), 2.0), np.full((4, 4, 3), 5.0)).any()
    assert glossy.ssim(a, a[::-1]).mean() < 0.5
    with pytest.raises(glossy.InputError, match=r"^test: expected shape \(height, width, 3\)"):
        glossy.ssim(a, a[..., 0])
    with pytest.raises(glossy.InputError, match=r"^reference and test: 30x20 and 20x30"):
        glossy.delta_e_itp(a, a.transpose(1, 0, 2))
    with pytest.raises(glossy.InputError, match=r"^white and black"):
        glossy.delta_e_itp(a, a, white=50, black=60)
