"""glossy's error per sample on the comparison scene: rel. RMSE x sqrt(spp) against glossy's converged image,
for the sample counts and seeds asked. Constant for plain 1/sqrt(N) convergence; lower is a better sampler.
What docs/performance.md quotes for the sampler (e.g. 64 against 90 spp). Asserts nothing.

Needs the scene and the converged images of scripts/compare-mitsuba (run it once); run with its venv:
  build/mitsuba-venv/bin/python bench/mitsuba/sampler_error.py --spp 64,90,128 --seeds 2
"""

import argparse
import math
import subprocess
import tempfile
from pathlib import Path

import numpy as np
import mitsuba as mi


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--build", default="build", help="glossy's build directory")
    p.add_argument("--spp", default="64,90,128", help="comma-separated sample counts")
    p.add_argument("--seeds", type=int, default=2, help="renders per count (seeds 5000, 5001, ...)")
    p.add_argument("--threads", type=int, default=2)
    a = p.parse_args()
    mi.set_variant("scalar_rgb")  # only for reading EXRs
    build = Path(a.build)
    scene = build / "compare"
    halves = sorted((scene / "ref").glob("glossy-256-d3-cook-torrance-*-1024spp-[ab].exr"))
    if len(halves) != 2:
        raise SystemExit(f"sampler_error.py: glossy's converged halves not found in {scene / 'ref'}; run scripts/compare-mitsuba")

    def read(path):
        return np.array(mi.Bitmap(str(path)), dtype=np.float64)[..., :3]

    ref = 0.5 * (read(halves[0]) + read(halves[1]))
    with tempfile.TemporaryDirectory() as tmp:
        jobs = [(int(spp), seed, Path(tmp) / f"{spp}-{seed}.exr") for spp in a.spp.split(",") for seed in range(a.seeds)]
        commands = "".join(f"render {spp} {5000 + seed} {a.threads} {out}\n" for spp, seed, out in jobs) + "quit\n"
        run = subprocess.run([str(build / "bench/glossy_compare"), "--scene", str(scene / "sphere.gltf"),
                              "--env", str(scene / "sky.exr")], input=commands, text=True, capture_output=True, check=True)
        seconds = [float(line.split()[1]) for line in run.stdout.splitlines() if line.startswith("ok")]
        print("| spp | seed | rel. RMSE | rel. RMSE x sqrt(spp) | seconds |\n|---|---|---|---|---|")
        for (spp, seed, out), s in zip(jobs, seconds):
            e = math.sqrt(np.mean((read(out) - ref) ** 2)) / math.sqrt(np.mean(ref ** 2))
            print(f"| {spp} | {5000 + seed} | {e:.5f} | {e * math.sqrt(spp):.4f} | {s:.3f} |")


if __name__ == "__main__":
    main()
