#include "renderer/image/colour_maps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace glossy {

namespace {

// A map as evenly spaced stops (0xRRGGBB), interpolated linearly between them in display values.
template <size_t N>
DisplayColour interpolate(const std::array<unsigned, N>& stops, double t) {
  t = std::clamp(t, 0.0, 1.0);
  const double x = t * double(N - 1);
  const size_t i = std::min(size_t(x), N - 2);
  const double f = x - double(i);
  DisplayColour c;
  for (int k = 0; k < 3; ++k) {
    const int shift = 16 - 8 * k;
    const double a = double((stops[i] >> shift) & 0xff), b = double((stops[i + 1] >> shift) & 0xff);
    c[size_t(k)] = float(((1.0 - f) * a + f * b) / 255.0);
  }
  return c;
}

// The published maps at 11 evenly spaced points (matplotlib's viridis, ColorBrewer's RdBu from its blue
// end): close enough to the full tables for pictures, and no table to keep.
constexpr std::array<unsigned, 11> kViridis = {0x440154, 0x482475, 0x414487, 0x355f8d, 0x2a788e, 0x21918c,
                                               0x22a884, 0x44bf70, 0x7ad151, 0xbddf26, 0xfde725};
constexpr std::array<unsigned, 11> kBlueWhiteRed = {0x053061, 0x2166ac, 0x4393c3, 0x92c5de, 0xd1e5f0, 0xf7f7f7,
                                                    0xfddbc7, 0xf4a582, 0xd6604d, 0xb2182b, 0x67001f};

}  // namespace

float srgbEncode(double v) {
  v = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0);
  return float(v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055);
}

DisplayColour divergingColour(double t) { return interpolate(kBlueWhiteRed, std::isnan(t) ? 0.5 : 0.5 * (t + 1.0)); }
DisplayColour viridisColour(double t) { return interpolate(kViridis, std::isnan(t) ? 0.0 : t); }

std::string hexColour(const DisplayColour& c) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", int(std::lround(std::clamp(c[0], 0.0f, 1.0f) * 255.0f)),
                int(std::lround(std::clamp(c[1], 0.0f, 1.0f) * 255.0f)), int(std::lround(std::clamp(c[2], 0.0f, 1.0f) * 255.0f)));
  return text;
}

}  // namespace glossy
