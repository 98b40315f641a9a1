#include "renderer/image/ssim.h"

#include "renderer/image/colour_maps.h"

#include <cmath>
#include <stdexcept>

namespace glossy {

namespace {

constexpr int kRadius = 5;
constexpr double kSigma = 1.5;

// A plane of one channel, filtered separably by the normalised Gaussian window.
struct Plane {
  int width, height;
  std::vector<double> v;
};

// The index a mirrored border reads: −1 → 0, −2 → 1, n → n − 1 (half-sample symmetric).
int mirrored(int i, int n) {
  while (i < 0 || i >= n) i = i < 0 ? -i - 1 : 2 * n - i - 1;
  return i;
}

Plane blurred(const Plane& in, const double (&weights)[2 * kRadius + 1]) {
  Plane rows{in.width, in.height, std::vector<double>(in.v.size())}, out = rows;
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      double s = 0.0;
      for (int k = -kRadius; k <= kRadius; ++k) s += weights[k + kRadius] * in.v[size_t(y) * in.width + mirrored(x + k, in.width)];
      rows.v[size_t(y) * in.width + x] = s;
    }
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      double s = 0.0;
      for (int k = -kRadius; k <= kRadius; ++k) s += weights[k + kRadius] * rows.v[size_t(mirrored(y + k, in.height)) * in.width + x];
      out.v[size_t(y) * in.width + x] = s;
    }
  return out;
}

}  // namespace

std::vector<float> ssimMap(const RgbImage& reference, const RgbImage& test) {
  if (reference.width != test.width || reference.height != test.height || reference.width <= 0 || reference.height <= 0)
    throw std::invalid_argument("ssimMap: the images differ in size or are empty");
  const int w = reference.width, h = reference.height;
  const size_t pixels = size_t(w) * size_t(h);
  if (reference.pixels.size() != 3 * pixels || test.pixels.size() != 3 * pixels)
    throw std::invalid_argument("ssimMap: a pixel buffer does not match its image's size");
  double weights[2 * kRadius + 1], total = 0.0;
  for (int k = -kRadius; k <= kRadius; ++k) total += weights[k + kRadius] = std::exp(-0.5 * k * k / (kSigma * kSigma));
  for (double& weight : weights) weight /= total;

  constexpr double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
  std::vector<float> map(pixels, 0.0f);
  for (int c = 0; c < 3; ++c) {
    Plane x{w, h, std::vector<double>(pixels)}, y = x, xx = x, yy = x, xy = x;
    for (size_t i = 0; i < pixels; ++i) {
      x.v[i] = srgbEncode(reference.pixels[3 * i + c]);
      y.v[i] = srgbEncode(test.pixels[3 * i + c]);
      xx.v[i] = x.v[i] * x.v[i];
      yy.v[i] = y.v[i] * y.v[i];
      xy.v[i] = x.v[i] * y.v[i];
    }
    const Plane mx = blurred(x, weights), my = blurred(y, weights), mxx = blurred(xx, weights), myy = blurred(yy, weights),
                mxy = blurred(xy, weights);
    for (size_t i = 0; i < pixels; ++i) {
      const double ux = mx.v[i], uy = my.v[i];
      const double vx = mxx.v[i] - ux * ux, vy = myy.v[i] - uy * uy, cxy = mxy.v[i] - ux * uy;
      const double s = (2.0 * ux * uy + c1) * (2.0 * cxy + c2) / ((ux * ux + uy * uy + c1) * (vx + vy + c2));
      map[i] += float(s / 3.0);
    }
  }
  return map;
}

}  // namespace glossy
