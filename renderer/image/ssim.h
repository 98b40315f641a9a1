// SSIM (Wang, Bovik, Sheikh, Simoncelli, "Image quality assessment: from error visibility to structural
// similarity", IEEE TIP 2004) of two images as the sheet's PNG shows them: each channel sRGB-encoded at
// exposure 0 (clamped to [0, 1]; NaN is black), so that it judges what a viewer sees, not HDR values.
//
// Per channel, with local means μ, variances σ² and covariance σ_xy under a Gaussian window (σ = 1.5 pixels,
// truncated at 5 pixels: the paper's 11 × 11 window; weights normalised; the image mirrored at its border,
// d c b a | a b c d):
//   SSIM = (2 μ_x μ_y + C1)(2 σ_xy + C2) / ((μ_x² + μ_y² + C1)(σ_x² + σ_y² + C2)),  C1 = 0.01², C2 = 0.03²
// (dynamic range 1), and a pixel's SSIM is the mean of its three channels'. 1: identical; lower: less alike.
// As scikit-image's structural_similarity computes it with gaussian_weights=True, sigma=1.5,
// use_sample_covariance=False, data_range=1 (tests/display_metrics_test.cpp validates the map against it).
#pragma once

#include "renderer/image/exr_image.h"

#include <vector>

namespace glossy {

// The per-pixel SSIM of two linear Rec. 709 images of one size, row-major, row 0 at the top. Throws
// std::invalid_argument on a size mismatch or a pixel buffer of the wrong size.
std::vector<float> ssimMap(const RgbImage& reference, const RgbImage& test);

}  // namespace glossy
