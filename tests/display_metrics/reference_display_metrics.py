#!/usr/bin/env python3
"""Per-pixel ΔE_ITP and SSIM maps from colour-science and scikit-image, the references
tests/display_metrics_test.cpp checks glossy's (renderer/image/delta_e_itp.h, renderer/image/ssim.h) against.
The display and encoding are glossy's, stated there: each linear Rec. 709 channel clamped to [0, 1] (NaN
black); ΔE_ITP of the light an SDR display of white 100 cd/m² and black 0.1 cd/m² shows; SSIM of the
sRGB-encoded values.

    reference_display_metrics.py --check
        exit 0 if colour and skimage import, else 3 with the reason on stderr
    reference_display_metrics.py W H REF.f32 TEST.f32 DE.f32 SSIM.f32 [REF TEST DE SSIM ...]
        images are raw little-endian float32 RGB, row 0 at the top; each map is written the same way
"""
import sys
import warnings

try:
    import numpy as np
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # colour warns that matplotlib is absent
        import colour
    from skimage.metrics import structural_similarity
except ImportError as e:  # the test skips, naming what is missing
    print(f"cannot import colour-science, scikit-image or numpy: {e}", file=sys.stderr)
    sys.exit(3)


def shown(path, w, h):
    rgb = np.fromfile(path, dtype="<f4").astype(np.float64).reshape(h, w, 3)
    return np.clip(np.nan_to_num(rgb, nan=0.0, posinf=1.0, neginf=0.0), 0.0, 1.0)


def ictcp(linear):
    light = 0.1 + (100.0 - 0.1) * linear
    rgb2020 = colour.RGB_to_RGB(light, colour.RGB_COLOURSPACES["ITU-R BT.709"], colour.RGB_COLOURSPACES["ITU-R BT.2020"])
    return colour.RGB_to_ICtCp(rgb2020)


def main(argv):
    if argv[1:] == ["--check"]:
        return 0
    if len(argv) < 7 or (len(argv) - 3) % 4 != 0:
        print(__doc__, file=sys.stderr)
        return 2
    w, h = int(argv[1]), int(argv[2])
    for i in range(3, len(argv), 4):
        ref, test = shown(argv[i], w, h), shown(argv[i + 1], w, h)
        delta = colour.difference.delta_E_ITP(ictcp(ref), ictcp(test))
        np.ascontiguousarray(delta, dtype="<f4").tofile(argv[i + 2])
        encode = lambda x: colour.cctf_encoding(x, function="sRGB")
        _, s = structural_similarity(encode(ref), encode(test), gaussian_weights=True, sigma=1.5, use_sample_covariance=False,
                                     data_range=1.0, channel_axis=2, full=True)
        np.ascontiguousarray(s.mean(axis=2), dtype="<f4").tofile(argv[i + 3])
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
