// The lat-long (equirectangular) parameterisation of directions and a bilinearly looked-up RGB map on it,
// with the spec's conventions (shared/spec/interfaces.md, = Mitsuba 3's envmap with identity transform):
// u = atan2(d_x, −d_z)/(2π) wrapped to [0,1), v = acos(d_y)/π; columns sit at texel centres
// (x = u·W − ½, wrapping), rows span pole to pole (y = v·(H − 1), row 0 exactly +Y).
#pragma once

#include "materials/core/types.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace glossy {

// x − ⌊x⌋, but never 1.0 (which a tiny negative x would round to).
inline double wrapUnit(double x) {
  const double w = x - std::floor(x);
  return w < 1.0 ? w : 0.0;
}

// (u, v) of a unit direction.
inline Vec2 latLongFromDirection(const Vec3& d) {
  const double u = wrapUnit(std::atan2(d.x, -d.z) * (0.5 * kInvPi));
  const double v = std::acos(std::clamp(d.y, -1.0, 1.0)) * kInvPi;
  return {u, v};
}

inline Vec3 directionFromLatLong(Vec2 uv) {
  const double theta = kPi * uv.y, phi = 2.0 * kPi * uv.x;
  const double sinTheta = std::sin(theta);
  return {sinTheta * std::sin(phi), std::cos(theta), -sinTheta * std::cos(phi)};
}

// Linear RGB texels, row-major from the top (+Y) row, in float (all that .hdr/.exr files hold anyway), each
// beside a spare float: the layout LatLongMap keeps, so that the image becomes the map without a copy (a
// 16k map's texels are 2 GB).
struct LatLongImage {
  static constexpr std::size_t kStride = 4;  // floats per texel: r, g, b, spare
  int width = 0;
  int height = 0;  // at least 2: rows are interpolated pole to pole
  std::vector<float> texels;

  LatLongImage() = default;
  LatLongImage(int w, int h) : width(w), height(h), texels(std::size_t(w) * std::size_t(h) * kStride, 0.0f) {}

  float* at(int column, int row) { return &texels[(std::size_t(row) * std::size_t(width) + std::size_t(column)) * kStride]; }
  const float* at(int column, int row) const {
    return &texels[(std::size_t(row) * std::size_t(width) + std::size_t(column)) * kStride];
  }
  Rgb texel(int column, int row) const {
    const float* t = at(column, row);
    return {t[0], t[1], t[2]};
  }

  // The centre of column i and row j in (u, v): where the map's value is exactly texel(i, j).
  Vec2 texelUv(int column, int row) const {
    return {(column + 0.5) / width, double(row) / double(height - 1)};
  }
};

// Where a bilinear lookup at (u, v) falls: columns c0, c1 = c0 + 1 (wrapping) and rows r0, r0 + 1, with
// the weights fx, fy of the second of each. A plain aggregate, always built whole: the batch lookups keep
// arrays of them that are not zeroed per call.
struct LatLongPosition {
  int c0, c1, r0;
  double fx, fy;
};

inline LatLongPosition latLongPosition(Vec2 uv, int width, int height) {
  const double x = uv.x * width - 0.5;
  const double x0 = std::floor(x);
  // x0 is −1 … W − 1 for u in [0, 1) (wrapUnit's range): −1 wraps to the last column, with no division.
  const int c0 = x0 < 0.0 ? width - 1 : std::min(int(x0), width - 1);
  const double y = std::clamp(uv.y, 0.0, 1.0) * (height - 1);
  const int r0 = std::min(int(y), height - 2);
  return {c0, c0 + 1 == width ? 0 : c0 + 1, r0, x - x0, y - r0};
}

// A LatLongImage's texels for the environment light's random lookups, and their bilinear interpolation at
// a lookup position, with a float per cell (bilinear patch) that the caller sets: the light's sampling
// density, which a lookup then reads from the lines it loads anyway. 16 bytes a texel (the image's own
// buffer), its RGB beside the value of the patch of which it is the top-left corner; a lookup's two
// texels of a row share a line three times in four.
class LatLongMap {
 public:
  LatLongMap() = default;
  // The image's buffer becomes the map's; every cell's value is 0 until set.
  explicit LatLongMap(LatLongImage image) : width_(image.width), height_(image.height), texels_(std::move(image.texels)) {
    for (std::size_t t = 0; t < texels_.size(); t += 4) texels_[t + 3] = 0.0f;
  }
  // Cell (i, j) is the patch between texels (i, j) and (i + 1, j + 1); j < H − 1.
  void setCellValue(int column, int row, float value) { texels_[offset(column, row) + 3] = value; }
  Rgb texel(int column, int row) const {
    const float* t = data(column, row);
    return {t[0], t[1], t[2]};
  }

  int width() const { return width_; }
  int height() const { return height_; }

  Rgb interpolate(const LatLongPosition& p) const {
    const float* corner[4];
    corners(p, corner);
    const auto rgb = [&](int k) { return Rgb(corner[k][0], corner[k][1], corner[k][2]); };
    const Rgb top = rgb(0) * (1.0 - p.fx) + rgb(1) * p.fx;
    const Rgb bottom = rgb(2) * (1.0 - p.fx) + rgb(3) * p.fx;
    return top * (1.0 - p.fy) + bottom * p.fy;
  }
  // The value given for the cell the lookup falls in.
  float cellValue(const LatLongPosition& p) const { return data(p.c0, p.r0)[3]; }
  // The luminance of each of the lookup's corners: (c0, r0), (c1, r0), (c0, r0 + 1), (c1, r0 + 1).
  void cornerLuminances(const LatLongPosition& p, double (&out)[4]) const {
    const float* corner[4];
    corners(p, corner);
    for (int k = 0; k < 4; ++k) out[k] = luminance(Rgb(corner[k][0], corner[k][1], corner[k][2]));
  }
  // The lines interpolate(at[k]) and cellValue(at[k]) will read, k < n. Always inlined: GCC 12 finds a
  // function of nothing but prefetches free of side effects and deletes calls to it before inlining, so a
  // call would prefetch nothing.
  [[gnu::always_inline]] void prefetch(const LatLongPosition* at, int n) const {
    for (int k = 0; k < n; ++k) {
      const float* corner[4];
      corners(at[k], corner);
      for (const float* c : corner) __builtin_prefetch(c);
    }
  }

 private:
  static_assert(LatLongImage::kStride == 4, "a texel is its RGB and its cell's value");
  std::size_t offset(int column, int row) const { return (std::size_t(row) * std::size_t(width_) + std::size_t(column)) * 4; }
  const float* data(int column, int row) const { return &texels_[offset(column, row)]; }
  // The corners (c0, r0), (c1, r0), (c0, r0 + 1), (c1, r0 + 1).
  void corners(const LatLongPosition& p, const float* (&out)[4]) const {
    out[0] = data(p.c0, p.r0);
    out[1] = data(p.c1, p.r0);
    out[2] = data(p.c0, p.r0 + 1);
    out[3] = data(p.c1, p.r0 + 1);
  }

  int width_ = 0, height_ = 0;
  std::vector<float> texels_;  // r, g, b, cell value
};

// Directions and lookup positions on a W × H lat-long map turned by uOffset (looked up at
// u_world + uOffset), by the spec's formulas, for whole batches at a time: θ = atan2(ρ, y) (= acos y for a
// unit direction, and as accurate near the poles), φ = atan2(x, −z), and back by sin and cos, all from
// lanes:: (libmvec), a few ns per lane where libm's scalar calls cost 20–30. The one-direction forms are
// batches of one, so they return exactly what the same direction gets in any batch.
class LatLongGrid {
 public:
  LatLongGrid() = default;
  LatLongGrid(int width, int height, double uOffset)
      : width_(width), height_(height), uOffset_(uOffset), rows_(height - 1) {}

  // out[k]: the lookup position of unit direction d[lanes[k]], k < n, what latLongPosition(uvOf(...))
  // gives (the same cell and weights up to rounding, and cells differing only on an edge). Any n.
  void positions(const Vec3* d, const int* lanes, int n, LatLongPosition* out) const;
  LatLongPosition position(const Vec3& d) const {
    const int lane = 0;
    LatLongPosition p;
    positions(&d, &lane, 1, &p);
    return p;
  }

  // out[i]: the unit direction at the weights of at[i] in its cell, and its sin θ. Any n.
  void directions(const LatLongPosition* at, Vec3* out, double* sinTheta, int n) const;
  Vec3 direction(int column, int row, double fx, double fy, double& sinTheta) const {
    const LatLongPosition at{column, column + 1 == width_ ? 0 : column + 1, row, fx, fy};
    Vec3 d;
    directions(&at, &d, &sinTheta, 1);
    return d;
  }

  // (u, v) in the map, by the spec's formulas (libm, one direction).
  Vec2 uvOf(const Vec3& d) const {
    Vec2 uv = latLongFromDirection(d);
    uv.x = wrapUnit(uv.x + uOffset_);
    return uv;
  }

 private:
  int width_ = 0, height_ = 0;
  double uOffset_ = 0.0;
  int rows_ = 0;  // of cells: H − 1
};

}  // namespace glossy
