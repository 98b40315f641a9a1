// Where a model differs from the measured panel, as pictures beside the sheet's figures: the signed relative
// difference of luminance, and HDR-ꟻLIP's perceptual error map (renderer/image/flip.h) with its mean over
// the object's pixels and a 95 % interval; and two more perceptual figures of the panels as the PNG shows
// them, each the mean of its map over the object with the same kind of interval: ΔE_ITP
// (renderer/image/delta_e_itp.h) and SSIM (renderer/image/ssim.h).
//
// Relative difference: d = (Y_p − Y_m) / max(Y_m, 0.01 Ȳ_m) on the object's pixels (Y: Rec. 709 luminance of
// the panels' mean images; Ȳ_m: the measured panel's mean luminance over the object), 0 elsewhere. The floor
// keeps the map finite where the measured panel is black; such pixels read as large errors, which they are
// relative to the object's light. The PNG shows d clamped to ±kRelativeDifferenceRange; the EXR keeps it.
//
// ꟻLIP is not linear in the images, so render noise raises it (noise is a difference ꟻLIP sees), and unlike
// the relative RMSE it has no unbiased form: it is non-smooth (absolute values, powers below 1, a maximum over
// exposures), and a jackknife bias correction was seen to overcorrect (tests/error_maps_test.cpp,
// docs/sheets.md). So the figure is the ꟻLIP of the two mean images as they are, F — what flip-evaluator
// reports for the EXR's layers — with an interval for the render noise's spread of F: the jackknife over the
// K coherent replicates, F_j the ꟻLIP of the means without replicate j, se² = (K − 1)/K Σ_j (F_j − mean F_j)²,
// F ± t(K − 1) · se. Beside it the sheet states the noise floor: the ꟻLIP between the measured panel's two
// halves of replicates, what noise alone shows (flipNoiseFloor). ΔE_ITP and SSIM are non-linear in the
// images as ꟻLIP is (a square root of squared differences; ratios of local moments), so they are treated
// alike: the figure of the two mean images, with the jackknife's interval for its render noise; noise alone
// raises ΔE_ITP and lowers SSIM, as the sheet's noise-floor row shows.
#pragma once

#include "renderer/image/exr_image.h"
#include "renderer/sheet/comparison.h"

#include <vector>

namespace glossy {

// The PNG's colour range of the relative difference: ±50 %.
inline constexpr double kRelativeDifferenceRange = 0.5;

struct ErrorMaps {
  bool available = false;                 // the measured panel has light over the object
  std::vector<float> relativeDifference;  // per panel pixel, row 0 at the top
  std::vector<float> flipMap;             // per panel pixel, over the whole panel (ꟻLIP's filters need the context)
  double flip = 0.0;                      // F: mean of `flipMap` over the object
  double deltaEItp = 0.0;                 // mean ΔE_ITP over the object
  double ssim = 0.0;                      // mean SSIM over the object (1: identical)
  bool hasCi = false;                     // K ≥ 3: the intervals below
  Interval flipCi, deltaEItpCi, ssimCi;   // the render noise's 95 % spread of each figure
};

// panel, measured: the K replicates of each (same count, one size); mask: the object's pixels.
ErrorMaps errorMaps(const std::vector<RgbImage>& panel, const std::vector<RgbImage>& measured, const std::vector<char>& mask);

// The ꟻLIP between the means of the first and the second half of the measured panel's replicates, over the
// mask: the figure noise alone gives, at half the samples of a panel. < 0 when there are fewer than 2.
double flipNoiseFloor(const std::vector<RgbImage>& measured, const std::vector<char>& mask);

}  // namespace glossy
