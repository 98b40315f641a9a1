#!/usr/bin/env python3
"""glossy.Brdf.eval from Python against the library's own C++ loop, on the same 10⁶ direction pairs.

Prints, per BRDF (every fit of a material, and measured data), the C++ loop's rate (brdf_eval_bench, one
thread), the Python call's with threads=1 (the same work plus the module's normalising and checking of
each direction) and their ratio, and the Python call's with all cores (its default).

    PYTHONPATH=build/python build/python-venv/bin/python bench/python_eval.py
"""
import argparse
import os
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np

import glossy

root = Path(__file__).resolve().parents[1]
parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--pairs", type=int, default=1_000_000)
parser.add_argument("--runs", type=int, default=5, help="timed calls per BRDF; the median is kept")
parser.add_argument("--material", default=str(root / "materials/library/merl/alum-bronze.toml"))
parser.add_argument("--measured", default=str(root.parent / "shared/merl/alum-bronze.binary.xz"))
parser.add_argument("--exe", default=str(root / "build/bench/brdf_eval_bench"))
args = parser.parse_args()

# Directions over the upper hemisphere, half of the L near V's mirror direction, where the lobes are.
rng = np.random.default_rng(2012)
V = rng.normal(size=(args.pairs, 3))
V[:, 2] = np.abs(V[:, 2])
V /= np.linalg.norm(V, axis=1, keepdims=True)
L = rng.normal(size=(args.pairs, 3))
L[:, 2] = np.abs(L[:, 2])
mirror = V * [-1, -1, 1]
L[: args.pairs // 2] = mirror[: args.pairs // 2] + 0.05 * L[: args.pairs // 2]
L /= np.linalg.norm(L, axis=1, keepdims=True)


def median_seconds(f):
    times = []
    for _ in range(args.runs):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return sorted(times)[len(times) // 2]


with tempfile.TemporaryDirectory() as tmp:
    pairs = Path(tmp) / "pairs.f64"
    np.hstack([L, V]).astype("<f8").tofile(pairs)
    command = [args.exe, "--pairs", str(pairs), "--material", args.material, "--runs", str(args.runs)]
    if os.path.exists(args.measured):
        command += ["--measured", args.measured]
    cpp = {line.split(",")[0]: float(line.split(",")[1])
           for line in subprocess.run(command, capture_output=True, text=True, check=True).stdout.splitlines()}

material = glossy.load_material(args.material)
brdfs = {fit: material.brdf(fit) for fit in material.fits}
if "measured" in cpp:
    brdfs["measured"] = glossy.load_merl(args.measured)
out = np.empty((args.pairs, 3))
print(f"{args.pairs} pairs, median of {args.runs}; Mpairs/s (higher is better)")
print(f"{'BRDF':24} {'C++ loop':>9} {'Python 1 thread':>16} {'ratio':>6} {'Python all cores':>17}")
ratios = []
for name, brdf in brdfs.items():
    one = median_seconds(lambda: brdf.eval(L, V, out=out, threads=1))
    every = median_seconds(lambda: brdf.eval(L, V, out=out))
    ratios.append(cpp[name] / one)
    print(f"{name:24} {args.pairs / cpp[name] / 1e6:9.2f} {args.pairs / one / 1e6:16.2f} {cpp[name] / one:6.2f} "
          f"{args.pairs / every / 1e6:17.2f}")
print(f"lowest ratio {min(ratios):.2f} (Python's rate / the C++ loop's, one thread each)")
