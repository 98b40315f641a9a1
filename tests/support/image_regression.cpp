#include "tests/support/image_regression.h"

#include "tests/support/chi2.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace glossy::test {

namespace {

namespace IBA = OIIO::ImageBufAlgo;

// Blocks of the local-bias test: large enough that a rare bright sample (a firefly the reference caught and
// the test did not) is averaged with enough pixels, small enough to see a bias confined to part of the object.
constexpr int kBlock = 16;

OIIO::ImageBuf toBuf(const RgbImage& img) {
  OIIO::ImageBuf buf(OIIO::ImageSpec(img.width, img.height, 3, OIIO::TypeDesc::FLOAT));
  if (!buf.set_pixels(buf.roi(), OIIO::TypeDesc::FLOAT, img.pixels.data())) throw std::runtime_error(buf.geterror());
  return buf;
}

OIIO::ImageBuf maskBuf(const std::vector<char>& mask, int w, int h) {
  OIIO::ImageBuf buf(OIIO::ImageSpec(w, h, 1, OIIO::TypeDesc::FLOAT));
  std::vector<float> v(mask.begin(), mask.end());
  if (!buf.set_pixels(buf.roi(), OIIO::TypeDesc::FLOAT, v.data())) throw std::runtime_error(buf.geterror());
  return buf;
}

double sumOver(const OIIO::ImageBuf& buf, OIIO::ROI roi) {
  const IBA::PixelStats stats = IBA::computePixelStats(buf, roi);
  return stats.avg.empty() ? 0.0 : double(stats.avg[0]) * double(stats.finitecount[0]);
}

}  // namespace

RgbImage crop(const RgbImage& image, int x, int y, int w, int h) {
  RgbImage out(w, h);
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      for (int c = 0; c < 3; ++c) out.at(i, j)[c] = image.at(x + i, y + j)[c];
  return out;
}

ImageComparison compareWithReference(const RgbImage& halfA, const RgbImage& halfB, int sppPerHalf, const RgbImage& reference,
                                     int referenceSpp, const std::vector<char>& mask, double alpha) {
  ImageComparison out;
  const int w = reference.width, h = reference.height;
  // On the sum of the channels: their noise is correlated (one path serves all three), so the variance of
  // the sum is estimated directly rather than added up.
  // Weights given explicitly: this OIIO reads past the single default weight.
  const float ones[3] = {1.0f, 1.0f, 1.0f};
  const OIIO::ImageBuf a = IBA::channel_sum(toBuf(halfA), ones), b = IBA::channel_sum(toBuf(halfB), ones);
  const OIIO::ImageBuf r = IBA::channel_sum(toBuf(reference), ones);
  const OIIO::ImageBuf m = maskBuf(mask, w, h);
  const OIIO::ImageBuf t = IBA::mul(IBA::add(a, b), 0.5f);
  const OIIO::ImageBuf halfDiff = IBA::mul(IBA::sub(a, b), 0.5f);
  const float refShare = float(1.0 + 2.0 * sppPerHalf / double(referenceSpp));
  const OIIO::ImageBuf variance = IBA::mul(IBA::mul(IBA::mul(halfDiff, halfDiff), refShare), m);
  const OIIO::ImageBuf diff = IBA::mul(IBA::sub(t, r), m);
  const OIIO::ImageBuf refMasked = IBA::mul(r, m);

  double sumD = 0.0, sumV = 0.0;
  for (int by = 0; by < h; by += kBlock)
    for (int bx = 0; bx < w; bx += kBlock) {
      const OIIO::ROI roi(bx, std::min(w, bx + kBlock), by, std::min(h, by + kBlock), 0, 1, 0, 1);
      const double d = sumOver(diff, roi), v = sumOver(variance, roi);
      sumD += d;
      sumV += v;
      if (sumOver(m, roi) < kBlock || !(v > 0.0)) continue;  // blocks with too few object pixels
      out.blockChi2 += d * d / v;
      ++out.blocks;
    }
  const double sumR = sumOver(refMasked, refMasked.roi());
  out.relativeBias = sumR > 0.0 ? sumD / sumR : 0.0;
  out.meanZ = sumV > 0.0 ? sumD / std::sqrt(sumV) : 0.0;
  out.meanP = std::erfc(std::abs(out.meanZ) / std::sqrt(2.0));
  out.blockP = out.blocks > 0 ? chi2Survival(out.blockChi2, out.blocks) : 1.0;
  out.passed = out.meanP >= alpha / 2 && out.blockP >= alpha / 2;

  const IBA::CompareResults cmp = IBA::compare(toBuf(halfA), toBuf(reference), 1.0f, 1.0f);
  std::ostringstream s;
  s << "relative bias " << out.relativeBias << " (z = " << out.meanZ << ", p = " << out.meanP << "); " << out.blocks
    << " blocks: χ² = " << out.blockChi2 << ", p = " << out.blockP << "; α/2 = " << alpha / 2
    << "; OIIO compare of one half: mean error " << cmp.meanerror << ", RMS " << cmp.rms_error << ", max " << cmp.maxerror;
  out.message = s.str();
  return out;
}

}  // namespace glossy::test
