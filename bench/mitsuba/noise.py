"""Noise at equal spp, glossy beside Mitsuba 3, on the comparison scene (issue 21): what each renderer's
estimator is worth per sample, which load on the machine does not change.

The scene of compare.py (bench/mitsuba/scene.py: the UV sphere, camera at (0, 1, 4), 35 deg, max depth 3)
with a Cook-Torrance fit of a material file, under a lat-long map or a constant radiance. Each renderer
renders 2 x PAIRS images with distinct seeds; a pair (a, b) estimates the per-pixel variance of one image as
mean((a - b)^2) / 2 over the sphere's pixels (compare.regions) and channels. Printed: the mean over pairs
of that variance, its square root ("noise"), and the images' mean over the sphere (the two renderers'
means should agree). Mitsuba: path integrator, llvm_ad_rgb, the sampler asked for (multijitter is the
stratified sampler that matches glossy's; independent shows what stratification is worth).

Run with the Mitsuba venv (scripts/compare-mitsuba makes one), after building glossy:
  DRJIT_LIBLLVM_PATH=... VENV/bin/python bench/mitsuba/noise.py --env path/to/map.hdr --pairs 3
  ... --env constant:1 --samplers multijitter,independent
"""

import argparse
import json
import math
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import scene as bench_scene  # noqa: E402

import drjit as dr  # noqa: E402
import mitsuba as mi  # noqa: E402

mi.set_variant("llvm_ad_rgb")
import cook_torrance  # noqa: E402  (needs the variant)
from compare import mitsuba_scene, regions, read_exr  # noqa: E402

cook_torrance.register()


def glossy_image(exe, scene, env, size, spp, seed, threads, max_depth, out):
    command = [str(exe), "render", "--scene", str(scene), "--spp", str(spp), "--seed", str(seed),
               "--threads", str(threads), "--width", str(size), "--height", str(size), "--max-depth", str(max_depth),
               "-o", str(out)]
    command += ["--env-constant", env.split(":", 1)[1]] if env.startswith("constant:") else ["--env", env]
    subprocess.run(command, check=True, capture_output=True)
    return read_exr(out)


def emitter_dict(env):
    if env.startswith("constant:"):
        return {"type": "constant", "radiance": {"type": "rgb", "value": float(env.split(":", 1)[1])}}
    return {"type": "envmap", "filename": env}


def variance(images, mask):
    pairs = [np.mean((images[2 * i][mask] - images[2 * i + 1][mask]) ** 2) / 2.0 for i in range(len(images) // 2)]
    return float(np.mean(pairs))


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--root", type=Path, default=HERE.parent.parent, help="glossy checkout")
    p.add_argument("--build", type=Path, default=None, help="glossy build folder (default ROOT/build)")
    p.add_argument("--env", required=True, help="lat-long map file, or constant:VALUE")
    p.add_argument("--material", default="materials/library/merl/blue-rubber.toml")
    p.add_argument("--fit", default="cook-torrance:E1")
    p.add_argument("--size", type=int, default=256)
    p.add_argument("--spp", type=int, default=64)
    p.add_argument("--pairs", type=int, default=3)
    p.add_argument("--threads", type=int, default=2)
    p.add_argument("--max-depth", type=int, default=3)
    p.add_argument("--samplers", default="multijitter", help="Mitsuba samplers, comma-separated")
    a = p.parse_args()
    root = a.root.resolve()
    exe = (a.build or root / "build").resolve() / "renderer/glossy"
    if not a.env.startswith("constant:"):
        a.env = str(Path(a.env).resolve())
    model, metric = a.fit.split(":")
    if model != "cook-torrance":
        raise SystemExit("noise.py: the Mitsuba side implements cook-torrance fits only")
    material = (root / a.material).resolve()
    fit = next(f for f in tomllib.loads(material.read_text())["fit"] if f["model"] == model and f["metric"] == metric)
    dr.set_thread_count(a.threads)
    mask = regions(a.size)["sphere"]
    seeds = [100 + k for k in range(2 * a.pairs)]
    results = []
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        bench_scene.write_scene(work, a.size, a.size, material, a.fit)
        runs = [("glossy", lambda seed: glossy_image(exe, work / "sphere.gltf", a.env, a.size, a.spp, seed, a.threads,
                                                     a.max_depth, work / "glossy.exr"))]
        for sampler in a.samplers.split(","):
            scene = mitsuba_scene(work, a.size, a.max_depth, cook_torrance.bsdf_dict(fit), sampler, emitter_dict(a.env))
            runs.append((f"mitsuba {sampler}",
                         lambda seed, scene=scene: np.array(mi.render(scene, spp=a.spp, seed=seed), dtype=np.float64)))
        for name, render in runs:
            images = [render(seed) for seed in seeds]
            v = variance(images, mask)
            results.append({"renderer": name, "variance": v, "noise": math.sqrt(v),
                            "mean": float(np.mean([im[mask].mean() for im in images]))})
    print(f"| renderer | noise | variance | variance / glossy's | mean over the sphere |\n|---|---|---|---|---|")
    for r in results:
        print(f"| {r['renderer']} | {r['noise']:.5f} | {r['variance']:.4g} | {r['variance'] / results[0]['variance']:.3f} "
              f"| {r['mean']:.5f} |")
    print(json.dumps({"env": a.env, "spp": a.spp, "pairs": a.pairs, "results": results}), file=sys.stderr)


if __name__ == "__main__":
    main()
