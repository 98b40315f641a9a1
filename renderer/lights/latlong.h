// The lat-long (equirectangular) parameterisation of directions and a bilinearly looked-up RGB map on it,
// with the spec's conventions (shared/spec/interfaces.md, = Mitsuba 3's envmap with identity transform):
// u = atan2(d_x, −d_z)/(2π) wrapped to [0,1), v = acos(d_y)/π; columns sit at texel centres
// (x = u·W − ½, wrapping), rows span pole to pole (y = v·(H − 1), row 0 exactly +Y).
#pragma once

#include "materials/core/types.h"
#include "materials/sampling/huge_pages.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
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

// Linear RGB texels, row-major from the top (+Y) row, 3 floats per texel: float halves the memory of a
// 4k map and is all that .hdr/.exr files hold anyway.
struct LatLongImage {
  int width = 0;
  int height = 0;  // at least 2: rows are interpolated pole to pole
  std::vector<float> rgb;

  Rgb texel(int column, int row) const {
    const float* t = &rgb[(std::size_t(row) * std::size_t(width) + std::size_t(column)) * 3];
    return {t[0], t[1], t[2]};
  }

  // The centre of column i and row j in (u, v): where the map's value is exactly texel(i, j).
  Vec2 texelUv(int column, int row) const {
    return {(column + 0.5) / width, double(row) / double(height - 1)};
  }

  // Bilinear lookup at (u, v) in [0,1)×[0,1].
  Rgb lookup(Vec2 uv) const;
};

// Where a bilinear lookup at (u, v) falls: columns c0, c1 = c0 + 1 (wrapping) and rows r0, r0 + 1, with
// the weights fx, fy of the second of each.
struct LatLongPosition {
  int c0 = 0, c1 = 0, r0 = 0;
  double fx = 0.0, fy = 0.0;
};

inline LatLongPosition latLongPosition(Vec2 uv, int width, int height) {
  const double x = uv.x * width - 0.5;
  const double x0 = std::floor(x);
  int c0 = int(x0) % width;
  if (c0 < 0) c0 += width;
  const double y = std::clamp(uv.y, 0.0, 1.0) * (height - 1);
  const int r0 = std::min(int(y), height - 2);
  return {c0, c0 + 1 == width ? 0 : c0 + 1, r0, x - x0, y - r0};
}

template <class Texel>
Rgb interpolateLatLong(const Texel& t00, const Texel& t10, const Texel& t01, const Texel& t11, double fx, double fy) {
  const Rgb top = Rgb(t00[0], t00[1], t00[2]) * (1.0 - fx) + Rgb(t10[0], t10[1], t10[2]) * fx;
  const Rgb bottom = Rgb(t01[0], t01[1], t01[2]) * (1.0 - fx) + Rgb(t11[0], t11[1], t11[2]) * fx;
  return top * (1.0 - fy) + bottom * fy;
}

inline Rgb LatLongImage::lookup(Vec2 uv) const {
  const LatLongPosition p = latLongPosition(uv, width, height);
  const auto at = [&](int column, int row) { return &rgb[(std::size_t(row) * std::size_t(width) + std::size_t(column)) * 3]; };
  return interpolateLatLong(at(p.c0, p.r0), at(p.c1, p.r0), at(p.c0, p.r0 + 1), at(p.c1, p.r0 + 1), p.fx, p.fy);
}

// The same texels in huge pages (huge_pages.h), for the environment light's random lookups; the same
// values as LatLongImage::lookup, bit for bit.
class LatLongMap {
 public:
  LatLongMap() = default;
  explicit LatLongMap(const LatLongImage& image)
      : width_(image.width), height_(image.height), rgb_(image.rgb.begin(), image.rgb.end()) {}

  int width() const { return width_; }
  int height() const { return height_; }

  Rgb interpolate(const LatLongPosition& p) const {
    return interpolateLatLong(at(p.c0, p.r0), at(p.c1, p.r0), at(p.c0, p.r0 + 1), at(p.c1, p.r0 + 1), p.fx, p.fy);
  }
  Rgb lookup(Vec2 uv) const { return interpolate(latLongPosition(uv, width_, height_)); }

 private:
  const float* at(int column, int row) const {
    return &rgb_[(std::size_t(row) * std::size_t(width_) + std::size_t(column)) * 3];
  }
  int width_ = 0, height_ = 0;
  HugePageVector<float> rgb_;
};

}  // namespace glossy
