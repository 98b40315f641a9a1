// ΔE_ITP (Recommendation ITU-R BT.2124, 2019): the colour difference of two images as a display shows them,
// in the ICtCp encoding of Rec. ITU-R BT.2100 (PQ). Kavoosighafi et al. ("Perceived quality of BRDF
// models", CGF 2025) found it the image metric closest to people's judgments of BRDF approximations.
//
// Per pixel, for each image:
//   displayed light   RGB_d = L_b + (L_w − L_b) · clamp(RGB, 0, 1)   in cd/m², Rec. 709 primaries: what the
//                     sheet's PNG (exposure 0, sRGB-encoded) shows on the display below;
//   BT.2020 RGB       M_709→2020 · RGB_d                               (Rec. ITU-R BT.2087);
//   LMS               (1/4096) [1688 2146 262; 683 2951 462; 99 309 3688] · RGB_2020;
//   L'M'S'            PQ inverse EOTF of LMS / 10000 (SMPTE ST 2084: m1 = 2610/16384, m2 = 2523/32,
//                     c1 = 3424/4096, c2 = 2413/128, c3 = 2392/128);
//   ICtCp             (1/4096) [2048 2048 0; 6610 −13613 7003; 17933 −17390 −543] · L'M'S';
// and ΔE_ITP = 720 · √(ΔI² + (ΔCt / 2)² + ΔCp²) — 1 is a just-noticeable difference at the most critical
// adaptation. The display is a common SDR one: white L_w = 100 cd/m², black L_b = 0.1 cd/m² (1000:1).
// Without a black level, PQ's steep foot would count a thousandth of a cd/m² in a shadow as a visible
// difference (ΔE_ITP 4.5 between 0 and 0.001 cd/m² of grey). A NaN channel displays as black, as in
// the PNG. Validated against colour-science's RGB_to_ICtCp and delta_E_ITP (tests/display_metrics_test.cpp).
#pragma once

#include "renderer/image/exr_image.h"

#include <vector>

namespace glossy {

struct SdrDisplay {
  double white = 100.0;  // cd/m², what (1, 1, 1) shows
  double black = 0.1;    // cd/m², what (0, 0, 0) shows
};

// The per-pixel ΔE_ITP between two linear Rec. 709 images of one size, row-major, row 0 at the top.
// Throws std::invalid_argument on a size mismatch or a pixel buffer of the wrong size.
std::vector<float> deltaEItpMap(const RgbImage& reference, const RgbImage& test, const SdrDisplay& display = {});

}  // namespace glossy
