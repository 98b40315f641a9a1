// LatLongGrid's batch conversions (latlong.h).
#include "renderer/lights/latlong.h"

#include "materials/core/lane_math.h"

namespace glossy {

namespace {
constexpr int kChunk = 128;  // lanes converted per pass, on the stack
}

void LatLongGrid::positions(const Vec3* d, const int* lanes, int n, LatLongPosition* out) const {
  for (int first = 0; first < n; first += kChunk) {
    const int count = std::min(kChunk, n - first);
    // θ and φ of every lane from one pass: y and x of the two atan2s side by side.
    double y[2 * kChunk], x[2 * kChunk], angle[2 * kChunk];
    for (int i = 0; i < count; ++i) {
      const Vec3& v = d[lanes[first + i]];
      y[i] = std::sqrt(v.x * v.x + v.z * v.z);
      x[i] = v.y;
      y[count + i] = v.x;
      x[count + i] = -v.z;
    }
    lanes::atan2(y, x, angle, 2 * count);
    for (int i = 0; i < count; ++i) {
      const double u = wrapUnit(wrapUnit(angle[count + i] * (0.5 * kInvPi)) + uOffset_);
      out[first + i] = latLongPosition({u, angle[i] * kInvPi}, width_, height_);
    }
  }
}

void LatLongGrid::directions(const LatLongPosition* at, Vec3* out, double* sinTheta, int n) const {
  for (int first = 0; first < n; first += kChunk) {
    const int count = std::min(kChunk, n - first);
    double angle[2 * kChunk], s[2 * kChunk], c[2 * kChunk];
    for (int i = 0; i < count; ++i) {
      const LatLongPosition& p = at[first + i];
      const double uMap = wrapUnit((p.c0 + p.fx + 0.5) / width_);
      angle[i] = kPi * ((p.r0 + p.fy) / rows_);                   // θ
      angle[count + i] = 2.0 * kPi * wrapUnit(uMap - uOffset_);  // φ
    }
    lanes::sinCos(angle, s, c, 2 * count);
    for (int i = 0; i < count; ++i) {
      sinTheta[first + i] = s[i];
      out[first + i] = {s[i] * s[count + i], c[i], -s[i] * c[count + i]};
    }
  }
}

}  // namespace glossy
