// The wave against the reference path tracer (reference_path.cpp), which shares none of its sampling, so
// the two can only agree in expectation. R renders of each (different seeds) are compared per square
// block of pixels and per channel: a block's mean over the renders has a standard error from each pixel's
// spread over them (pixels are independent, so a block's variance is its pixels' summed).
#pragma once

#include "materials/models/brdf.h"
#include "renderer/image/exr_image.h"

#include <vector>

namespace glossy::test {

struct BlockCheck {
  // The largest |difference of the means| over its combined standard error: tests ask for < 4.5, about one
  // false alarm in 150,000 comparisons.
  double worstZ = 0.0;
  // Over the blocks that carry the image (at least a tenth of its brightest block's mean), the largest
  // relative bias that would be 6.8 standard errors (4.5 + 2.3): caught with 99 % probability.
  double worstDetectable = 0.0;
  int lit = 0;  // the block channels counted in worstDetectable
};

BlockCheck compareBlocks(const std::vector<RgbImage>& wave, const std::vector<RgbImage>& reference, int blockSize);

// A configuration the wave treats differently from a plain path, on a sphere over a floor (SphereOnFloor,
// render_fixtures.h) seen at 40 × 32 pixels.
struct TracerCase {
  enum class Sky { None, Default, Panels };  // no environment, the built-in sky, a map of small bright panels
  const char* name;
  Brdf brdf;  // the sphere's
  bool lamp;
  Sky sky;
  int maxDepth = 8, rouletteDepth = 100;
  int lightSamples = 4;
  bool perBrdf = true;  // RenderSettings::lightSamplesPerBrdf
  // The wave's samples per pixel at which a 16 × 16 block's test catches a bias of 1 % with 99 % probability
  // (measured on the default suite's 8 × 8 blocks at 64, with a margin of 1.3 on the samples).
  int sppForOnePercent = 2048;
};

// The environment alone (its batch lookups), with emitters (lights chosen by power, per-light batches),
// emitters alone, a measured table (no batch forms), Russian roulette, depth 1 (emitters only), one light
// sample, three everywhere, and a sharp lobe (one light sample, several BSDF samples at the first vertex)
// whose samples are traced (a lamp emits) or resampled (none does), under the sky and under small bright
// panels.
std::vector<TracerCase> tracerCases();

// Four renders of the case by each tracer, the wave at waveSpp and the reference at four times that (its
// samples are cheaper and noisier), compared in blocks of blockSize pixels. Prints one line of figures.
BlockCheck compareTracers(const TracerCase& c, int waveSpp, int blockSize);

}  // namespace glossy::test
