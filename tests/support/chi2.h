// χ² goodness-of-fit test of a direction sampler against the density it claims to draw from, in the style of
// Mitsuba 3's and pbrt-v4's sampler tests, with cells that follow the lobe so that a lobe a few milliradians
// wide is resolved (the published fits reach AS n = 6.2e5, ABC B = 8.1e6, CT m = 0.0018).
//
// The histogram lives on the upper hemisphere in spherical coordinates (θ, φ) of L. Cell edges are packed
// around a centre direction (the mirror direction of V): θ = θc + σ sinh(t), φ = φc + σ_φ sinh(t) with t
// uniform, so cells near the peak are a fraction of the lobe width σ while a few dozen cells still cover the
// whole hemisphere. The horizon θ = π/2 is a cell edge, so a density that jumps there is integrated exactly.
// Expected counts are the pdf integrated over each cell by adaptive Gauss-Legendre quadrature; samples the
// sampler rejects form one more cell, whose expected count is N (1 − ∫pdf): a pdf whose integral exceeds 1,
// or that disagrees with the sampler's acceptance rate, fails like any other mismatch.
#pragma once

#include "materials/core/types.h"

#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace glossy::test {

// A partition of the upper hemisphere of L into cells, with the integral of a density over each cell.
class Chi2Grid {
 public:
  virtual ~Chi2Grid() = default;
  virtual int cellCount() const = 0;
  // The cell holding L (unit, L.z > 0); −1 below the horizon.
  virtual int cellOf(const Vec3& L) const = 0;
  // ∫ f(L) dω_L over the cell; f must be 0 below the horizon.
  virtual double integrate(int cell, const std::function<double(const Vec3&)>& f) const = 0;
  virtual std::string describe(int cell) const = 0;  // for messages
};

// Cells in (θ, φ) of L packed around a centre direction (see above).
class LobeGrid : public Chi2Grid {
 public:
  // centre: unit vector with centre.z ≥ 0; sigma: the lobe's angular width (radians).
  LobeGrid(const Vec3& centre, double sigma, int thetaCells, int phiCells);

  int cellCount() const override { return int(thetaEdges_.size() - 1) * int(phiEdges_.size() - 1); }
  int cellOf(const Vec3& L) const override;
  double integrate(int cell, const std::function<double(const Vec3&)>& f) const override;
  std::string describe(int cell) const override;

 private:
  double thetaC_, phiC_;
  std::vector<double> thetaEdges_, phiEdges_;  // φ edges relative to φc, spanning [−π, π]
  double thetaSigma_, phiSigma_, tTheta0_, dtTheta_, tPhi0_, dtPhi_;
};

// Cells in half-vector space for a fixed V: x = 1 − cos θ_h between the given edges × φ_h − φ_v in equal
// steps over [−π, π); L = reflect(V, H), dω_L = 4⟨V,H⟩ dω_H, dω_H = dx dφ. For tabulated samplers whose
// density is constant on half-vector cells: with the grid's edges on (or subdividing) the sampler's, each
// cell's integral is exact wherever its reflection stays above the horizon.
class HalfVectorGrid : public Chi2Grid {
 public:
  HalfVectorGrid(const Vec3& V, std::vector<double> xEdges, int phiCells);

  int cellCount() const override { return int(xEdges_.size() - 1) * phiCells_; }
  int cellOf(const Vec3& L) const override;
  double integrate(int cell, const std::function<double(const Vec3&)>& f) const override;
  std::string describe(int cell) const override;

 private:
  Vec3 V_;
  double phiV_;
  std::vector<double> xEdges_;
  int phiCells_;
};

// Draws one direction toward the light (std::nullopt for a rejected/invalid sample) from the rng.
using DirectionSampler = std::function<std::optional<Vec3>(std::mt19937_64&)>;
using DirectionPdf = std::function<double(const Vec3&)>;

struct Chi2Result {
  bool passed = false;
  double statistic = 0.0, pValue = 0.0;
  int degreesOfFreedom = 0;
  int cells = 0, pooledCells = 0;
  double pdfIntegral = 0.0;   // ∫ pdf over the upper hemisphere (the sampler's claimed acceptance)
  double acceptance = 0.0;    // fraction of samples the sampler accepted
  std::string message;        // what went wrong, or a summary; worst cells included
};

// Draws `samples` directions with a std::mt19937_64 seeded with `seed`, bins them on `grid` and compares
// with the counts `pdf` predicts. Fails when the p-value is below `alpha`, when a sample lands where the
// pdf integrates to zero, or when ∫pdf exceeds 1.
Chi2Result chi2Test(const DirectionSampler& sampler, const DirectionPdf& pdf, const Chi2Grid& grid,
                    long samples, unsigned seed, double alpha);

// The per-test significance that keeps the family-wise error rate at familyAlpha over `tests` independent
// tests (Šidák): 1 − (1 − familyAlpha)^(1/tests).
double sidakAlpha(double familyAlpha, int tests);

// P(X ≥ x) for X ~ χ²(dof): the regularised upper incomplete gamma Q(dof/2, x/2).
double chi2Survival(double x, int dof);

// Pearson's χ² of observed counts against expected ones, bins expected to hold fewer than minExpected
// pooled into one (kept if it reaches minExpected itself); p is its survival at bins − 1 degrees of
// freedom (1 when there is at most one bin).
struct PooledChi2 {
  double statistic = 0.0, p = 1.0;
  int bins = 0;
};
PooledChi2 pooledChi2(const std::vector<double>& observed, const std::vector<double>& expected, double minExpected = 5.0);

}  // namespace glossy::test
