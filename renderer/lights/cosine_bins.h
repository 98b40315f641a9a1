// The first stage of the environment's sampling toward a surface: which cell of the map to draw from,
// chosen for the receiving normal. A light sample at a surface brings L·ρ·cos θ, and cos θ is zero for
// half the sphere: drawn by the map's light alone, a studio map's bright panels below a point's horizon
// take a large share of its samples and give nothing, and those near its horizon give little. So the
// normals are put into bins (a cube's faces, 16 × 16 each), and each bin keeps its own distribution over
// the map's cells: a cell's light times the largest cos θ that any normal of the bin makes with any
// direction of the cell.
//
// That factor is a bound, not an estimate, so that no direction that can bring light gets density 0 (a
// cell wholly below the horizon of every normal in the bin gets nothing, as it can bring nothing): its
// cosine only shapes the density, and every sample is weighted by its own exact pdf. The bin of a zero
// normal is the unweighted one, which draws cells by their light alone (Environment::sample(u)).
//
// Inside a cell the map's own distribution (nested_grid.h) takes over, so the bins cost a fixed 13 MB
// whatever the map's size.
#pragma once

#include "materials/core/types.h"

#include <cstddef>
#include <span>
#include <vector>

namespace glossy {

class CosineBins {
 public:
  static constexpr int kFaceBins = 16;  // bins along each side of the cube's faces
  static constexpr int kUnweighted = 6 * kFaceBins * kFaceBins;  // the bin of the zero normal

  // A cell's directions: all within `radius` radians of the unit vector `axis`.
  struct Cone {
    Vec3 axis;
    double radius;
  };

  CosineBins() = default;
  // The map's cells, row-major (cell (cc, cr) at cr·cellColumns + cc): their light (≥ 0, finite) and the
  // cones that hold their directions.
  CosineBins(std::size_t cellColumns, std::size_t cellRows, std::span<const double> light, std::span<const Cone> cones);

  // The bin of a normal (any length); kUnweighted for zero or non-finite vectors.
  static int bin(const Vec3& normal);
  // The cone of bin b's normals (b < kUnweighted).
  static Cone binCone(int b);

  struct Cell {
    std::size_t column, row;
  };
  // A cell drawn for bin b with u in [0,1)²: u.x picks its row, u.y its column, each becoming its position
  // within what it picked (in [0,1)).
  Cell sample(int b, Vec2& u) const;
  // The probability that sample(b, ·) draws cell (cc, cr).
  double probability(int b, std::size_t cc, std::size_t cr) const;

 private:
  const float* table(int b) const { return &tables_[std::size_t(b) * stride_]; }
  std::size_t columns_ = 0, rows_ = 0, stride_ = 0;
  // Per bin: the CDF over cell rows (rows_ floats), then each row's CDF over its cells (rows_ × columns_).
  std::vector<float> tables_;
};

}  // namespace glossy
