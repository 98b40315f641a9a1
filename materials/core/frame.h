// An orthonormal shading frame around a unit normal (Duff et al. 2017, "Building an Orthonormal Basis,
// Revisited": branchless and continuous except at one point). BRDFs live in this frame with N = +z.
#pragma once

#include "materials/core/types.h"

#include <cmath>

namespace glossy {

struct Frame {
  Vec3 s, t, n;

  explicit Frame(const Vec3& normal) : n(normal) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    s = Vec3(1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    t = Vec3(b, sign + n.y * n.y * a, -n.y);
  }
  Vec3 toLocal(const Vec3& w) const { return {dot(w, s), dot(w, t), dot(w, n)}; }
  Vec3 toWorld(const Vec3& w) const { return s * w.x + t * w.y + n * w.z; }

 private:
  static double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
};

}  // namespace glossy
