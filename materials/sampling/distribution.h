// Piecewise-constant probability densities on [0,1) and [0,1)², sampled by exact inversion of their CDFs
// (after pbrt's Distribution1D/2D). Distribution2D samples the measured BRDFs' half vectors; the light
// chooser uses Distribution1D. (The environment's tables are compact CDFs in cells: nested_grid.h.)
//
// A tabulated function f of n non-negative bins defines the density p(x) = f(⌊x·n⌋) / ∫f on [0,1).
// Degenerate tables never produce NaN: when every value is zero the density is uniform (p ≡ 1), so the
// caller still gets valid samples and must weight them by its own (zero) integrand. Everything is double:
// maps of a million texels with a bright sun span more than float's CDF resolution.
//
// sample / pdf / the inversions allocate nothing and are safe to call concurrently.
#pragma once

#include "materials/core/types.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace glossy {

class Distribution1D {
 public:
  Distribution1D() = default;
  // values: the bins' non-negative, finite weights (throws std::invalid_argument otherwise, or if empty).
  explicit Distribution1D(std::span<const double> values);

  std::size_t size() const { return values_.size(); }
  double value(std::size_t bin) const { return values_[bin]; }
  // ∫₀¹ f(x) dx = mean of the values; 0 for an all-zero table (whose density is then uniform).
  double integral() const { return integral_; }
  // cdf[i] = P(x < i/n); cdf[0] = 0 and cdf[n] = 1 exactly.
  std::span<const double> cdf() const { return cdf_; }

  // Inverts the CDF: returns x in [0,1) with P(X < x) = u (piecewise linear within a bin). u outside [0,1)
  // is clamped into it. Never lands in a zero-weight bin (unless all are zero). pdf = p(x), offset = bin.
  double sampleContinuous(double u, double* pdf = nullptr, std::size_t* offset = nullptr) const;
  // The bin containing u in the CDF, with its probability mass; for choosing among discrete items.
  std::size_t sampleDiscrete(double u, double* probability = nullptr) const;

  double pdf(double x) const;  // density p(x); 0 outside [0,1] (x = 1 counts as the last bin)
  double discreteProbability(std::size_t bin) const;

 private:
  std::size_t binOf(double u) const;  // the bin whose CDF interval [cdf[i], cdf[i+1]) holds u
  double density(std::size_t bin) const;

  std::vector<double> values_;
  std::vector<double> cdf_;
  // guide_[k] = binOf(k/n): a lookup starts there (see findBin in the .cpp).
  std::vector<uint32_t> guide_;
  double integral_ = 0.0;
};

// A density on the unit square [0,1)² from a width × height table, row-major (values[y·width + x]),
// x along the first coordinate. Sampled as the marginal over rows, then the chosen row's conditional.
// Rows whose values are all zero have probability 0; an all-zero table is uniform (pdf ≡ 1).
//
// The conditionals are one Distribution1D per row in all but storage: their CDFs and guide tables sit in
// one array each, and the density of every cell (the marginal's times the row's, the product pbrt forms
// per call) in a third, so that a sample touches a few cache lines of one row and pdf() a single value.
class Distribution2D {
 public:
  struct Sample {
    Vec2 point;          // in [0,1)²
    double pdf;          // with respect to area on the unit square
    std::size_t column, row;  // the cell holding point
  };

  Distribution2D() = default;
  Distribution2D(std::span<const double> values, std::size_t width, std::size_t height);

  std::size_t width() const { return width_; }
  std::size_t height() const { return marginal_.size(); }
  double integral() const { return marginal_.integral(); }  // ∫∫ f over the unit square

  // u in [0,1)² (clamped). pdf(sample(u).point) == sample(u).pdf exactly.
  Sample sample(Vec2 u) const;
  double pdf(Vec2 point) const;  // 0 outside [0,1]²
  double cellDensity(std::size_t column, std::size_t row) const { return density_[row * width_ + column]; }

 private:
  std::size_t width_ = 0;
  Distribution1D marginal_;       // over rows, weighted by each row's integral
  std::vector<double> cdf_;      // row y's CDF at [y·(width + 1), (y + 1)·(width + 1))
  std::vector<uint32_t> guide_;  // row y's guide table at [y·width, (y + 1)·width)
  std::vector<double> density_;  // p(cell) = marginal density × conditional density, row-major
};

}  // namespace glossy
