// The lat-long (equirectangular) parameterisation of directions and a bilinearly looked-up RGB map on it,
// with the spec's conventions (shared/spec/interfaces.md, = Mitsuba 3's envmap with identity transform):
// u = atan2(d_x, −d_z)/(2π) wrapped to [0,1), v = acos(d_y)/π; columns sit at texel centres
// (x = u·W − ½, wrapping), rows span pole to pole (y = v·(H − 1), row 0 exactly +Y).
#pragma once

#include "materials/core/types.h"

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
  Rgb lookup(Vec2 uv) const {
    const double x = uv.x * width - 0.5;
    const double x0 = std::floor(x);
    const double fx = x - x0;
    int c0 = int(x0) % width;
    if (c0 < 0) c0 += width;
    const int c1 = c0 + 1 == width ? 0 : c0 + 1;

    const double y = std::clamp(uv.y, 0.0, 1.0) * (height - 1);
    const int r0 = std::min(int(y), height - 2);
    const double fy = y - r0;

    const Rgb top = texel(c0, r0) * (1.0 - fx) + texel(c1, r0) * fx;
    const Rgb bottom = texel(c0, r0 + 1) * (1.0 - fx) + texel(c1, r0 + 1) * fx;
    return top * (1.0 - fy) + bottom * fy;
  }
};

}  // namespace glossy
