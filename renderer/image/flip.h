// HDR-ꟻLIP: a perceptual error map between a rendered image and its reference, for the sheets' per-panel
// figures. LDR-ꟻLIP (Andersson et al. 2020, "ꟻLIP: A Difference Evaluator for Alternating Images", HPG)
// compares two images in [0,1] as a viewer flipping between them would: both are filtered by the eye's
// contrast sensitivity (achromatic, red-green and blue-yellow, at the viewing condition's pixels per
// degree), their colour difference is taken in a Hunt-adjusted CIELAB with the HyAB distance, and raised
// where edges and points (Gaussian first and second derivatives of the lightness) differ. HDR-ꟻLIP
// (Andersson et al. 2021, "Visualizing Errors in Rendered High Dynamic Range Images", Eurographics short
// paper) runs LDR-ꟻLIP on a series of exposures, each tone mapped by ACES, spanning from the exposure that
// brings the reference's brightest pixel to 85 % of the display to the one that brings its median there,
// and keeps each pixel's largest error. The exposure range comes from the reference alone, so every test
// image compared with one reference is judged on the same exposures.
//
// Validated against NVIDIA's flip-evaluator 1.7 (tests/flip_test.cpp, docs/flip.md).
#pragma once

#include "renderer/image/exr_image.h"

#include <vector>

namespace glossy {

struct FlipSettings {
  double pixelsPerDegree = 67.0;  // the papers' default viewing condition (0.7 m from a 0.7 m wide 4K display)
};

struct FlipMap {
  int width = 0, height = 0;
  std::vector<float> error;  // per pixel in [0,1], row-major, row 0 at the top
  double mean = 0.0;         // over all pixels
};

// The exposures HDR-ꟻLIP takes from a reference: stops start, start + step, ..., stop (count ≥ 2 of them),
// as in the paper: start = log2(x_max / Y_max), stop = log2(x_max / Y_median), where ACES maps x_max to
// 0.85 and Y is the reference's luminance; count = max(2, ceil(stop − start)).
struct FlipExposures {
  float start = 0.0f, stop = 0.0f;
  int count = 2;
};
// Y_median is floored at 2^-23 (FLT_EPSILON), as flip-evaluator ≥ 1.7 does for a reference at least half
// black; so is Y_max (where flip-evaluator stops with an error instead: a black reference), so that
// start ≤ stop always. Non-finite luminances are left out of the maximum and the median (flip-evaluator's
// result for them depends on where they sit).
FlipExposures hdrFlipExposures(const RgbImage& reference);

// HDR-ꟻLIP of `test` against `reference` (linear RGB). Throws std::invalid_argument on a size mismatch,
// an empty image, a pixel buffer of the wrong size, or pixels per degree outside (0, 1000].
// Inputs are treated as flip-evaluator treats them: each channel is exposed, tone mapped and clamped to
// [0,1]. The tone curve is a ratio of quadratics, so negative input is not black: an exposed channel below
// −0.02 maps above 0 and one below −0.4 to 1. A NaN, an infinity, or a value so large that its exposed
// square overflows a float maps to ∞/∞ = NaN and counts as 0. The map is finite and in [0,1] for any input.
FlipMap hdrFlip(const RgbImage& reference, const RgbImage& test, const FlipSettings& settings = {});

}  // namespace glossy
