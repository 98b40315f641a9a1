// What the piecewise-constant distributions share about [0, 1): its top, clamping into it, and a point
// placed within one of n equal bins.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace glossy {

// The largest double below 1: the top of every sampled range, so callers can index with ⌊x·n⌋.
inline constexpr double kOneMinusEpsilon = 1.0 - 0x1p-53;

// u clamped into [0, 1); NaN goes to 0 rather than propagating into an index.
inline double clampUnit(double u) { return u >= 0.0 ? std::min(u, kOneMinusEpsilon) : 0.0; }

// (bin + fraction) / n for fraction in [0, 1), kept inside bin `bin`: rounding in the division can step
// into a neighbour, and the bin reported and the one the point lies in must agree.
inline double pointInBin(std::size_t bin, double fraction, std::size_t n) {
  const double bins = double(n);
  double x = (double(bin) + fraction) / bins;
  while (x * bins >= double(bin + 1)) x = std::nextafter(x, 0.0);
  while (x * bins < double(bin)) x = std::nextafter(x, 1.0);
  return x;
}

}  // namespace glossy
