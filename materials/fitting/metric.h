// The fitting metrics of Löw et al. 2012 on glossy's fixed direction grid (docs/fitting.md):
//   E1 term = [(ρ_model − ρ_data) cos θ_i]² sin θ_i
//   E2 term = [ln(1 + ρ_model cos θ_i) − ln(1 + ρ_data cos θ_i)]² sin θ_i
// summed over R, G, B and over the grid's direction pairs whose MERL bin is measured, and reported as
//   E = sqrt(Σ terms / Σ sin θ_i).
// The grid: incident rings θ_i = (i + ½)°, i = 0..89, azimuths φ_i = ±2j°, j = 0..90 (180 azimuths, the
// negative ones exact mirror images of the positive ones); outgoing elevations
// θ_o = (5k + ½)°, k = 0..14 (up to 70.5°), at φ_o = 0. Every θ_o is an incident ring and φ_i = 180° is on the grid, so
// each slice holds its exact mirror pair. The data come from the reference nearest-bin lookup.
// Views stop at 70.5° because beyond it the 1°-wide MERL bins hold values that differ by far more than the
// lobe between their corners (⟨N,V⟩ changes by a factor 1.3 across a bin at 85°): with views up to 85.5°
// the round trips of tests/fitting_test.cpp recovered Kd 15-23 % off under E1, and within 1 % without them.
#pragma once

#include "materials/merl/merl_table.h"
#include "materials/models/brdf.h"

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace glossy {

enum class Metric { E1, E2 };
std::string_view metricName(Metric metric);
// "E1" | "E2"; throws InputError mentioning `context` otherwise.
Metric parseMetric(std::string_view text, std::string_view context);

// The metric's transform T of a BRDF value at incidence cos θ_i: the terms are w (T(ρ_model) − T(ρ_data))².
inline double metricTransform(Metric metric, double rho, double cosI) {
  return metric == Metric::E1 ? rho * cosI : std::log1p(rho * cosI);
}

struct MetricGrid {
  static constexpr int kThetaI = 90, kPhiI = 180, kThetaO = 15;
  static constexpr double kThetaIStepDeg = 1.0, kPhiIStepDeg = 2.0, kThetaOStepDeg = 5.0;
  static double thetaI(int i) { return (i + 0.5) * kThetaIStepDeg * kPi / 180.0; }
  static double phiI(int j) { return j * kPhiIStepDeg * kPi / 180.0; }
  static double thetaO(int k) { return (k * kThetaOStepDeg + 0.5) * kPi / 180.0; }
  static constexpr size_t kPairs = size_t(kThetaI) * kPhiI * kThetaO;  // 243,000
  // One line for files and reports: "θi 90 × φi 180 × θo 15 (φo = 0), nearest-bin MERL lookup".
  static std::string describe();
};

// The measured data on the grid, in the least-squares form a fitter needs. The pairs (θ_i, ±φ_i) have the
// same value under any isotropic model, so each mirror pair is one point whose target is the mean of its
// (one or two) valid members' T(ρ_data); the spread of the data about that mean is a constant:
//   Σ terms = Σ_points weight · Σ_c (T(ρ_model)_c − target_c)² + constant,  weight = members · sin θ_i.
class MetricData {
 public:
  struct Point {
    Vec3 L, V;
    double cosI;
    double weight;
    Rgb target;
  };

  // Throws InputError naming the table when no grid pair falls in a measured bin, or a value is not finite.
  MetricData(const MerlTable& table, Metric metric);

  Metric metric() const { return metric_; }
  const std::vector<Point>& points() const { return points_; }
  size_t validPairs() const { return validPairs_; }
  const std::string& source() const { return source_; }

  // E from a sum of weighted squared residuals over the points: sqrt((sum + constant) / weightSum).
  double errorFromSum(double weightedSquares) const {
    return std::sqrt(std::max(0.0, weightedSquares + constant_) / weightSum_);
  }
  // E of any BRDF against the data, through its eval().
  double error(const Brdf& brdf) const;

 private:
  Metric metric_;
  std::vector<Point> points_;
  double constant_ = 0.0, weightSum_ = 0.0;  // weightSum_: Σ sin θ_i over the valid pairs
  size_t validPairs_ = 0;
  std::string source_;
};

}  // namespace glossy
