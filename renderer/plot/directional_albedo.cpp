#include "renderer/plot/directional_albedo.h"

#include <algorithm>
#include "materials/sampling/gauss_legendre.h"

#include <array>
#include <cmath>
#include <vector>

namespace glossy::plot {

namespace {

constexpr int kNodes = 16;
constexpr int kPanelsToZero = 40;    // [x_max 2^-40, x_max 2^-39], …: below 2^-40 (θ_h < 1.4e-6 rad) no lobe lives
constexpr int kPanelsToHorizon = 8;  // toward the angles where L's range of φ_h starts to shrink, and where it ends

}  // namespace

double directionalAlbedo(const std::function<double(const Vec3& L, const Vec3& V)>& rho, double thetaV) {
  static const GaussLegendre<kNodes> gl;
  const double sv = std::sin(thetaV), cv = std::cos(thetaV);
  const Vec3 V(sv, 0.0, cv);
  // θ_h up to which every φ_h keeps L above the horizon, and past which none does.
  const double xFull = 1.0 - std::cos(std::max(0.0, kPi / 4.0 - thetaV / 2.0));
  const double xMax = 1.0 - std::cos(kPi / 4.0 + thetaV / 2.0);

  std::vector<double> edges = {0.0, xMax};
  for (int k = kPanelsToZero; k >= 1; --k) edges.push_back(std::ldexp(xMax, -k));
  // a(x) has square-root kinks where it leaves π (at xFull) and where it reaches 0 (at xMax): panels halve
  // toward both from inside the stretch between them (toward xMax from xMax / 2 when xFull = 0).
  const double from = xFull > 0.0 && xFull < xMax ? xFull : xMax / 2.0, d = (xMax - from) / 2.0;
  if (xFull > 0.0 && xFull < xMax) edges.push_back(xFull);
  for (int k = 0; k < kPanelsToHorizon; ++k) {
    edges.push_back(xMax - std::ldexp(d, -k));
    if (from == xFull) edges.push_back(xFull + std::ldexp(d, -k));
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());

  // ∫ over φ_h in [−a, a] for one x, as two panels (the integrand need not be even in φ_h: measured data).
  auto overPhi = [&](double x) {
    const double cosH = 1.0 - x, sinH = std::sqrt(x * (2.0 - x));
    const double A = sv * 2.0 * sinH * cosH, B = cv * (2.0 * cosH * cosH - 1.0);  // L_z ∝ A cos φ + B
    double a = kPi;
    if (A > 1e-300) a = std::acos(std::clamp(-B / A, -1.0, 1.0));
    else if (B <= 0.0) return 0.0;
    double sum = 0.0;
    for (int half = 0; half < 2; ++half) {
      const double lo = half ? 0.0 : -a, hi = half ? a : 0.0, h = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
      for (int i = 0; i < kNodes; ++i) {
        const double phi = mid + h * gl.x[i];
        const Vec3 H(sinH * std::cos(phi), sinH * std::sin(phi), cosH);
        const double vh = V.x * H.x + V.z * H.z;
        const Vec3 L = 2.0 * vh * H - V;
        if (L.z <= 0.0 || vh <= 0.0) continue;
        const double r = rho(L, V);
        if (std::isfinite(r)) sum += gl.w[i] * h * r * L.z * 4.0 * vh;
      }
    }
    return sum;
  };

  double total = 0.0;
  for (size_t p = 0; p + 1 < edges.size(); ++p) {
    const double lo = edges[p], hi = edges[p + 1], h = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
    if (h <= 0.0) continue;
    for (int i = 0; i < kNodes; ++i) total += gl.w[i] * h * overPhi(mid + h * gl.x[i]);
  }
  return total;
}

}  // namespace glossy::plot
