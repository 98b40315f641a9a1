// Rusinkiewicz's half/difference angles (θ_h, θ_d, φ_d) back to a direction pair (L, V) in the local frame
// (N = +z), with φ_h = 0: the inverse of the MERL lookup's to-half/difference rotation (spec/merl.md), so
// the figures' slices sample exactly the coordinates MERL tabulates.
#pragma once

#include "materials/core/types.h"

#include <cmath>
#include <utility>

namespace glossy::plot {

// The nominal slice angles (θ_d = 30°, φ_d = 90°, …) are MERL bin edges, where one rounding picks one bin and
// the next its neighbour, so a measured curve would zigzag between two bins. The slices sample a hair inside
// the bin that starts there: this many degrees, far above rounding (1e-14°), far below anything a fit shows.
inline constexpr double kInsideBinDeg = 1e-6;

// Angles in radians. D = (sin θ_d cos φ_d, sin θ_d sin φ_d, cos θ_d) in the half-vector frame, rotated
// about y by θ_h gives L; V is L reflected about H = (sin θ_h, 0, cos θ_h).
inline std::pair<Vec3, Vec3> directionsFromHalfDiff(double thetaH, double thetaD, double phiD) {
  const double sd = std::sin(thetaD), cd = std::cos(thetaD), ct = std::cos(thetaH), st = std::sin(thetaH);
  const Vec3 d(sd * std::cos(phiD), sd * std::sin(phiD), cd);
  const Vec3 L(d.x * ct + d.z * st, d.y, -d.x * st + d.z * ct);
  const Vec3 H(st, 0.0, ct);
  const Vec3 V = 2.0 * (L.x * H.x + L.z * H.z) * H - L;
  return {L, V};
}

}  // namespace glossy::plot
