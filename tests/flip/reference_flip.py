#!/usr/bin/env python3
"""HDR-FLIP means and maps from NVIDIA's flip-evaluator, the reference tests/flip_test.cpp checks glossy's
HDR-FLIP (renderer/image/flip.h) against.

    reference_flip.py --check
        exit 0 if flip_evaluator imports, else 3 with the reason on stderr
    reference_flip.py PPD REF.exr TEST.exr MAP.f32 [REF TEST MAP ...]
        for each triple, one line on stdout: mean start_exposure stop_exposure exposure_count (full
        precision), and the error map written to MAP as raw little-endian float32, row 0 at the top
"""
import sys

try:
    import numpy as np
    import flip_evaluator
except ImportError as e:  # the test skips, naming what is missing
    print(f"cannot import flip_evaluator or numpy: {e}", file=sys.stderr)
    sys.exit(3)


def main(argv):
    if argv[1:] == ["--check"]:
        return 0
    if len(argv) < 5 or (len(argv) - 2) % 3 != 0:
        print(__doc__, file=sys.stderr)
        return 2
    ppd = float(argv[1])
    for i in range(2, len(argv), 3):
        ref, test, out = argv[i], argv[i + 1], argv[i + 2]
        error, mean, params = flip_evaluator.evaluate(
            flip_evaluator.load(ref), flip_evaluator.load(test), "HDR", applyMagma=False, parameters={"ppd": ppd})
        np.ascontiguousarray(error[:, :, 0], dtype="<f4").tofile(out)
        print(repr(float(mean)), repr(float(params["startExposure"])), repr(float(params["stopExposure"])),
              int(params["numExposures"]), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
