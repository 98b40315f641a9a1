#include "renderer/image/delta_e_itp.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace glossy {

namespace {

using Vec = std::array<double, 3>;

Vec times(const double (&m)[3][3], const Vec& v) {
  return {m[0][0] * v[0] + m[0][1] * v[1] + m[0][2] * v[2], m[1][0] * v[0] + m[1][1] * v[1] + m[1][2] * v[2],
          m[2][0] * v[0] + m[2][1] * v[1] + m[2][2] * v[2]};
}

// Rec. ITU-R BT.2087's Rec. 709 → BT.2020 matrix for linear light, to the digits it is usually quoted with.
constexpr double kRec709To2020[3][3] = {{0.627403895934699, 0.329283038377884, 0.043313065687417},
                                        {0.069097289358232, 0.919540395075459, 0.011362315566309},
                                        {0.016391438875150, 0.088013307877226, 0.895595253247624}};
constexpr double kRgbToLms[3][3] = {{1688.0 / 4096, 2146.0 / 4096, 262.0 / 4096},
                                    {683.0 / 4096, 2951.0 / 4096, 462.0 / 4096},
                                    {99.0 / 4096, 309.0 / 4096, 3688.0 / 4096}};
constexpr double kLmsToIctcp[3][3] = {{2048.0 / 4096, 2048.0 / 4096, 0.0},
                                      {6610.0 / 4096, -13613.0 / 4096, 7003.0 / 4096},
                                      {17933.0 / 4096, -17390.0 / 4096, -543.0 / 4096}};

// SMPTE ST 2084's inverse EOTF: absolute luminance in cd/m² to the PQ signal in [0, 1].
double pq(double candelas) {
  constexpr double m1 = 2610.0 / 16384, m2 = 2523.0 / 4096 * 128, c1 = 3424.0 / 4096, c2 = 2413.0 / 4096 * 32,
                   c3 = 2392.0 / 4096 * 32;
  const double y = std::pow(std::clamp(candelas / 10000.0, 0.0, 1.0), m1);
  return std::pow((c1 + c2 * y) / (1.0 + c3 * y), m2);
}

Vec ictcp(const float* rgb, const SdrDisplay& display) {
  Vec light;
  for (int c = 0; c < 3; ++c) {
    const double v = std::isnan(rgb[c]) ? 0.0 : std::clamp(double(rgb[c]), 0.0, 1.0);
    light[c] = display.black + (display.white - display.black) * v;
  }
  Vec lms = times(kRgbToLms, times(kRec709To2020, light));
  for (double& x : lms) x = pq(x);
  return times(kLmsToIctcp, lms);
}

}  // namespace

std::vector<float> deltaEItpMap(const RgbImage& reference, const RgbImage& test, const SdrDisplay& display) {
  if (reference.width != test.width || reference.height != test.height)
    throw std::invalid_argument("deltaEItpMap: the images differ in size");
  const size_t pixels = size_t(reference.width) * size_t(reference.height);
  if (reference.pixels.size() != 3 * pixels || test.pixels.size() != 3 * pixels)
    throw std::invalid_argument("deltaEItpMap: a pixel buffer does not match its image's size");
  std::vector<float> map(pixels);
  for (size_t i = 0; i < pixels; ++i) {
    const Vec a = ictcp(&reference.pixels[3 * i], display), b = ictcp(&test.pixels[3 * i], display);
    const double di = a[0] - b[0], dt = 0.5 * (a[1] - b[1]), dp = a[2] - b[2];
    map[i] = float(720.0 * std::sqrt(di * di + dt * dt + dp * dp));
  }
  return map;
}

}  // namespace glossy
