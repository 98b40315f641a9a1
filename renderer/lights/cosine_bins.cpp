#include "renderer/lights/cosine_bins.h"

#include "renderer/lights/compact_cdf.h"

#include <glm/geometric.hpp>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace glossy {

namespace {

constexpr int kN = CosineBins::kFaceBins;

// Face f is the cube's side where axis f/2 is largest in magnitude, positive for even f; its other two
// axes, in order, are (f/2 + 1) mod 3 and (f/2 + 2) mod 3, each spanning [−1, 1] in kN bins.
Vec3 facePoint(int face, double s, double t) {
  const int a = face / 2;
  Vec3 p(0.0);
  p[a] = face % 2 == 0 ? 1.0 : -1.0;
  p[(a + 1) % 3] = s;
  p[(a + 2) % 3] = t;
  return glm::normalize(p);
}

double angle(const Vec3& a, const Vec3& b) { return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)); }

// Rounding in the cones' angles is far below this; it keeps a bound from cutting off a direction at the
// very edge of its cone.
constexpr double kMargin = 1e-6;

}  // namespace

int CosineBins::bin(const Vec3& n) {
  const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  int a = 0;
  double m = ax;
  if (ay > m) a = 1, m = ay;
  if (az > m) a = 2, m = az;
  if (!(m > 0.0) || !std::isfinite(m)) return kUnweighted;
  const int face = 2 * a + (n[a] < 0.0 ? 1 : 0);
  const auto index = [&](double x) { return std::clamp(int((x / m + 1.0) * 0.5 * kN), 0, kN - 1); };
  const double s = n[(a + 1) % 3], t = n[(a + 2) % 3];
  if (!std::isfinite(s) || !std::isfinite(t)) return kUnweighted;
  return (face * kN + index(s)) * kN + index(t);
}

CosineBins::Cone CosineBins::binCone(int b) {
  const int face = b / (kN * kN), i = (b / kN) % kN, j = b % kN;
  const auto edge = [](int k) { return -1.0 + 2.0 * k / kN; };
  const Vec3 axis = facePoint(face, 0.5 * (edge(i) + edge(i + 1)), 0.5 * (edge(j) + edge(j + 1)));
  // The bin is a spherical quadrilateral with great-circle sides (the cube's face seen from its centre):
  // its farthest point from any point inside is a corner.
  double radius = 0.0;
  for (int di = 0; di < 2; ++di)
    for (int dj = 0; dj < 2; ++dj) radius = std::max(radius, angle(axis, facePoint(face, edge(i + di), edge(j + dj))));
  return {axis, radius + kMargin};
}

CosineBins::CosineBins(std::size_t cellColumns, std::size_t cellRows, std::span<const double> light,
                       std::span<const Cone> cones)
    : columns_(cellColumns), rows_(cellRows), stride_(cellRows + cellRows * cellColumns) {
  const std::size_t cells = cellColumns * cellRows;
  if (cells == 0 || light.size() != cells || cones.size() != cells)
    throw std::invalid_argument("CosineBins: one light and one cone per cell");
  tables_.resize(std::size_t(kUnweighted + 1) * stride_);
  struct Trig {
    Vec3 axis;
    double radius, cos, sin;
  };
  std::vector<Trig> cell(cells);
  for (std::size_t c = 0; c < cells; ++c)
    cell[c] = {cones[c].axis, cones[c].radius + kMargin, std::cos(cones[c].radius + kMargin), std::sin(cones[c].radius + kMargin)};

  // bin's tables from the cells' weights for it.
  const auto build = [&](int b, const std::vector<double>& weights) {
    float* t = &tables_[std::size_t(b) * stride_];
    std::vector<double> rowWeight(rows_);
    for (std::size_t r = 0; r < rows_; ++r)
      rowWeight[r] = compact_cdf::build(&weights[r * columns_], columns_, t + rows_ + r * columns_);
    compact_cdf::build(rowWeight.data(), rows_, t);
  };
  tbb::parallel_for(0, kUnweighted + 1, [&](int b) {
    std::vector<double> weights(cells);
    if (b == kUnweighted) {
      for (std::size_t c = 0; c < cells; ++c) weights[c] = light[c];
      return build(b, weights);
    }
    const Cone bin = binCone(b);
    const double cosBin = std::cos(bin.radius), sinBin = std::sin(bin.radius);
    for (std::size_t c = 0; c < cells; ++c) {
      if (!(light[c] > 0.0)) {
        weights[c] = 0.0;
        continue;
      }
      // The largest cos θ over the two cones: cos(max(0, α − R)), α the angle between their axes and R
      // the sum of their radii, from the sums' cos and sin (no trigonometry per pair).
      const double cosR = cosBin * cell[c].cos - sinBin * cell[c].sin;
      const double sinR = sinBin * cell[c].cos + cosBin * cell[c].sin;
      const double cosAlpha = std::clamp(glm::dot(bin.axis, cell[c].axis), -1.0, 1.0);
      const bool overlapping = bin.radius + cell[c].radius >= kPi || cosAlpha >= cosR;
      const double bound = overlapping ? 1.0 : cosAlpha * cosR + std::sqrt(1.0 - cosAlpha * cosAlpha) * sinR;
      weights[c] = light[c] * std::max(bound, 0.0);
    }
    build(b, weights);
  });
}

CosineBins::Cell CosineBins::sample(int b, Vec2& u) const {
  const float* t = table(b);
  const std::size_t row = compact_cdf::sample(t, rows_, u.x);
  const std::size_t column = compact_cdf::sample(t + rows_ + row * columns_, columns_, u.y);
  return {column, row};
}

double CosineBins::probability(int b, std::size_t cc, std::size_t cr) const {
  const float* t = table(b);
  return compact_cdf::share(t, cr) * compact_cdf::share(t + rows_ + cr * columns_, cc);
}

}  // namespace glossy
