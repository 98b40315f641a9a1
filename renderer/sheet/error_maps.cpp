#include "renderer/sheet/error_maps.h"

#include "materials/core/types.h"
#include "renderer/image/delta_e_itp.h"
#include "renderer/image/flip.h"
#include "renderer/image/masked_mean.h"
#include "renderer/image/ssim.h"

#include <cmath>
#include <stdexcept>

namespace glossy {

namespace {

RgbImage meanOf(const std::vector<RgbImage>& replicates, size_t leftOut) {
  RgbImage mean(replicates.front().width, replicates.front().height);
  const double n = double(replicates.size() - (leftOut < replicates.size() ? 1 : 0));
  for (size_t j = 0; j < replicates.size(); ++j) {
    if (j == leftOut) continue;
    for (size_t i = 0; i < mean.pixels.size(); ++i) mean.pixels[i] += float(replicates[j].pixels[i] / n);
  }
  return mean;
}

double luminanceAt(const RgbImage& image, size_t pixel) {
  const float* p = &image.pixels[3 * pixel];
  return luminance(Rgb(p[0], p[1], p[2]));
}

// Student's t at 97.5 % for the jackknife's K − 1 degrees of freedom (K ≤ kReplicates = 4 in sheets).
double tQuantile975(size_t dof) {
  static const double table[] = {0.0, 12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228};
  return dof < std::size(table) ? table[dof] : 1.96;
}

// The jackknife's 95 % half-width of a figure from its K leave-one-out values F_j:
// t(K − 1) · √((K − 1)/K · Σ_j (F_j − mean F_j)²).
double jackknifeHalfWidth(const std::vector<double>& partial) {
  const size_t k = partial.size();
  double mean = 0.0;
  for (double f : partial) mean += f / double(k);
  double ss = 0.0;
  for (double f : partial) ss += (f - mean) * (f - mean);
  return tQuantile975(k - 1) * std::sqrt(double(k - 1) / double(k) * ss);
}

}  // namespace

ErrorMaps errorMaps(const std::vector<RgbImage>& panel, const std::vector<RgbImage>& measured, const std::vector<char>& mask) {
  ErrorMaps maps;
  if (panel.empty() || panel.size() != measured.size())
    throw std::invalid_argument("errorMaps: the panel and the measured panel need the same number of replicates");
  const size_t k = panel.size(), pixels = mask.size();
  const RgbImage p = meanOf(panel, k), m = meanOf(measured, k);
  if (p.pixels.size() != 3 * pixels || m.pixels.size() != 3 * pixels) throw std::invalid_argument("errorMaps: image and mask sizes differ");

  double sum = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < pixels; ++i)
    if (mask[i] && std::isfinite(luminanceAt(m, i))) {
      sum += luminanceAt(m, i);
      ++count;
    }
  if (count == 0 || !(sum > 0.0)) return maps;
  maps.available = true;
  const double floor = 0.01 * sum / double(count);
  maps.relativeDifference.assign(pixels, 0.0f);
  for (size_t i = 0; i < pixels; ++i) {
    if (!mask[i]) continue;
    const double yp = luminanceAt(p, i), ym = luminanceAt(m, i);
    const double d = (yp - ym) / std::max(ym, floor);
    maps.relativeDifference[i] = std::isfinite(d) ? float(d) : 0.0f;
  }

  maps.flipMap = hdrFlip(m, p).error;
  maps.flip = maskedMean(maps.flipMap, mask);
  maps.deltaEItp = maskedMean(deltaEItpMap(m, p), mask);
  maps.ssim = maskedMean(ssimMap(m, p), mask);
  if (k < 3) return maps;
  std::vector<double> flips(k), deltas(k), ssims(k);
  for (size_t j = 0; j < k; ++j) {
    const RgbImage mj = meanOf(measured, j), pj = meanOf(panel, j);
    flips[j] = maskedMean(hdrFlip(mj, pj).error, mask);
    deltas[j] = maskedMean(deltaEItpMap(mj, pj), mask);
    ssims[j] = maskedMean(ssimMap(mj, pj), mask);
  }
  const double flipHalf = jackknifeHalfWidth(flips), deltaHalf = jackknifeHalfWidth(deltas), ssimHalf = jackknifeHalfWidth(ssims);
  maps.hasCi = true;
  maps.flipCi = {std::max(0.0, maps.flip - flipHalf), std::min(1.0, maps.flip + flipHalf)};
  maps.deltaEItpCi = {std::max(0.0, maps.deltaEItp - deltaHalf), maps.deltaEItp + deltaHalf};
  maps.ssimCi = {std::max(-1.0, maps.ssim - ssimHalf), std::min(1.0, maps.ssim + ssimHalf)};
  return maps;
}

double flipNoiseFloor(const std::vector<RgbImage>& measured, const std::vector<char>& mask) {
  if (measured.size() < 2) return -1.0;
  const size_t half = measured.size() / 2;
  const std::vector<RgbImage> first(measured.begin(), measured.begin() + std::ptrdiff_t(half)),
      second(measured.begin() + std::ptrdiff_t(half), measured.end());
  return maskedMean(hdrFlip(meanOf(first, first.size()), meanOf(second, second.size())).error, mask);
}

}  // namespace glossy
