// Comparing a render with a reference render of the same scene, with a tolerance derived from the noise of
// both (no hand-tuned constant). The test render is given as two independent halves A and B (other seeds,
// equal spp): their mean is the test image, and ((A − B)/2)² estimates each pixel's variance of that mean.
// The reference's variance is the same scaled by testSpp / referenceSpp (same estimator, more samples).
//
// Statistics, over the masked pixels, on the sum of the three channels:
//   - the mean difference, as z = Σ(t − r) / sqrt(Σ(var_t + var_r)): a uniform bias;
//   - blocks of 16 × 16 pixels, χ² = Σ_b z_b²: a bias confined to part of the image.
// Each is judged at alpha / 2 (Bonferroni over the two).
#pragma once

#include "renderer/image/exr_image.h"

#include <string>
#include <vector>

namespace glossy::test {

struct ImageComparison {
  bool passed = false;
  double meanZ = 0.0, meanP = 0.0;  // the uniform-bias test
  double blockChi2 = 0.0, blockP = 0.0;
  int blocks = 0;
  double relativeBias = 0.0;  // Σ(t − r) / Σ r
  std::string message;
};

ImageComparison compareWithReference(const RgbImage& halfA, const RgbImage& halfB, int sppPerHalf, const RgbImage& reference,
                                     int referenceSpp, const std::vector<char>& mask, double alpha);

// The w × h region at (x, y) of an image.
RgbImage crop(const RgbImage& image, int x, int y, int w, int h);

}  // namespace glossy::test
