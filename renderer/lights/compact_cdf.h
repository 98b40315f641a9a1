// Discrete distributions stored as compact CDFs: the many small tables of the environment's sampling
// (cosine_bins.h, nested_grid.h), in float, or in 16 bits where a table is the size of the map.
//
// A CDF of n children is n entries, c[k] = the share of children 0 … k, c[n − 1] = 1 (a float, or a count
// of 1/65535ths). Each child with weight keeps a share however faint (a float CDF gives it at least 2⁻²²
// of the total, more than float's rounding near 1; a 16-bit one at least one count), so the CDF strictly
// rises at it: a child that can carry light is never given density 0, which MIS would divide by. A child
// of zero weight has no share and is never drawn; all zeros draw uniformly. share() reads back exactly
// what sample() draws with, so an estimator that divides by it stays unbiased.
#pragma once

#include "materials/sampling/unit_interval.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace glossy::compact_cdf {

constexpr double kUnit16 = 1.0 / 65535.0;

inline double value(const float* cdf, std::size_t k) { return cdf[k]; }
inline double value(const uint16_t* cdf, std::size_t k) { return cdf[k] * kUnit16; }

// cdf[0 … n) from weights[0 … n) (finite, ≥ 0); returns their sum. 16-bit tables hold at most 65535
// children.
inline double build(const double* weights, std::size_t n, float* cdf) {
  double total = 0.0;
  for (std::size_t k = 0; k < n; ++k) total += weights[k];
  if (!(total > 0.0)) {
    for (std::size_t k = 0; k < n; ++k) cdf[k] = float(double(k + 1) / double(n));
    cdf[n - 1] = 1.0f;
    return 0.0;
  }
  const double floor = total * 0x1p-22;
  double floored = 0.0;
  for (std::size_t k = 0; k < n; ++k) floored += weights[k] > 0.0 ? std::max(weights[k], floor) : 0.0;
  double sum = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    sum += weights[k] > 0.0 ? std::max(weights[k], floor) : 0.0;
    cdf[k] = float(sum / floored);
  }
  // The last positive child ends the CDF exactly; those after it have no share.
  std::size_t last = n;
  while (last > 0 && !(weights[last - 1] > 0.0)) --last;
  for (std::size_t k = last - 1; k < n; ++k) cdf[k] = 1.0f;
  return total;
}

inline double build(const double* weights, std::size_t n, uint16_t* cdf) {
  double total = 0.0;
  std::size_t positive = 0;
  for (std::size_t k = 0; k < n; ++k) {
    total += weights[k];
    positive += weights[k] > 0.0 ? 1 : 0;
  }
  if (!(total > 0.0)) {
    for (std::size_t k = 0; k < n; ++k) cdf[k] = uint16_t(std::lround(double(k + 1) / double(n) * 65535.0));
    return 0.0;
  }
  // Each positive child: its rounded running share, but at least one count above the one before and at
  // most what leaves one count for each positive child after it (the last positive one ends at 65535).
  double sum = 0.0;
  long previous = 0;
  std::size_t after = positive;
  for (std::size_t k = 0; k < n; ++k) {
    if (weights[k] > 0.0) {
      sum += weights[k];
      --after;
      const long ideal = std::lround(sum / total * 65535.0);
      previous = std::clamp(ideal, previous + 1, 65535L - long(after));
    }
    cdf[k] = uint16_t(previous);
  }
  return total;
}

// Child k's share.
template <class T>
double share(const T* cdf, std::size_t k) {
  return value(cdf, k) - (k > 0 ? value(cdf, k - 1) : 0.0);
}

// The child u (in [0, 1)) falls in; u becomes its position within that child's share, in [0, 1).
// Monotone in u, so a stratified u stays stratified. The child is the number of CDF values at or below u
// (children without a share are passed over), found by halving without branches (conditional moves, where a
// binary search's branches would mispredict half the time).
template <class T>
std::size_t sample(const T* cdf, std::size_t n, double& u) {
  // The count lies in [base, base + length]: the values before base are ≤ u, those from base + length on
  // are above it.
  std::size_t base = 0, length = n;
  while (length > 1) {
    const std::size_t half = length / 2;
    base = value(cdf, base + half - 1) <= u ? base + half : base;
    length -= half;
  }
  std::size_t child = base + (value(cdf, base) <= u ? 1 : 0);
  if (child >= n) {
    // u ≥ 1, past every value: the last child with a share.
    child = n - 1;
    while (child > 0 && !(share(cdf, child) > 0.0)) --child;
  }
  const double lower = child > 0 ? value(cdf, child - 1) : 0.0;
  u = clampUnit((u - lower) / (value(cdf, child) - lower));
  return child;
}

}  // namespace glossy::compact_cdf
