#include "materials/models/merl_sampling.h"

#include "materials/merl/merl_table.h"
#include "materials/models/brdf_sample.h"
#include "materials/models/half_vector.h"

#include <algorithm>
#include <cmath>

namespace glossy {

namespace {

constexpr double kTwoPi = 2.0 * kPi;

// 1 − cos θ without cancellation.
double oneMinusCos(double theta) {
  const double s = std::sin(0.5 * theta);
  return 2.0 * s * s;
}

}  // namespace

MerlSampling::MerlSampling(const MerlTable& table) {
  for (int i = 0; i <= kThetaBins; ++i) {
    const double f = double(i) / kThetaBins;
    xEdges_[i] = oneMinusCos(f * f * kPi / 2.0);
  }
  std::vector<double> weights(size_t(kThetaBins) * kPhiBins);
  views_.reserve(kViewBins);
  for (int k = 0; k < kViewBins; ++k) {
    const double thetaV = (k + 0.5) / kViewBins * (kPi / 2.0);
    const Vec3 V(std::sin(thetaV), 0.0, std::cos(thetaV));
    for (int i = 0; i < kThetaBins; ++i) {
      const double dx = xEdges_[i + 1] - xEdges_[i];
      for (int j = 0; j < kPhiBins; ++j) {
        double sum = 0.0;
        for (int a = 0; a < 2; ++a)
          for (int b = 0; b < 2; ++b) {
            const double x = xEdges_[i] + (a + 0.5) * 0.5 * dx;
            const double phi = -kPi + (j + (b + 0.5) * 0.5) * (kTwoPi / kPhiBins);
            Vec3 L;
            if (!reflectAboutHalfVector(V, x, phi, L) || L.z <= 0.0) continue;
            const Rgb rho = table.eval(L, V);
            sum += meanOf(rho) * L.z * 4.0 * HalfVector(L, V).cosVH;
          }
        // The cell's integral of the H-space integrand, up to a constant: mean value × solid angle ∝ Δx.
        weights[size_t(i) * kPhiBins + j] = 0.25 * sum * dx;
      }
    }
    views_.emplace_back(weights, kPhiBins, kThetaBins);
  }
}

MerlSampling::ViewPosition MerlSampling::viewPosition(const Vec3& V) {
  const double thetaV = std::atan2(std::hypot(V.x, V.y), V.z);
  const double s = thetaV / (kPi / 2.0) * kViewBins - 0.5;
  if (!(s > 0.0)) return {0, 0, 0.0};
  if (s >= kViewBins - 1) return {kViewBins - 1, kViewBins - 1, 0.0};
  const int k0 = int(s);
  return {k0, k0 + 1, s - k0};
}

bool MerlSampling::sample(const Vec3& V, double uChoice, Vec2 u, Vec3& L) const {
  const ViewPosition p = viewPosition(V);
  const int k = (p.t > 0.0 && uChoice >= 1.0 - p.t) ? p.k1 : p.k0;
  const Vec2 point = views_[k].sample(u).point;
  const double rows = point.y * kThetaBins;
  const int i = std::min(int(rows), kThetaBins - 1);
  const double x = xEdges_[i] + (rows - i) * (xEdges_[i + 1] - xEdges_[i]);
  const double phi = std::atan2(V.y, V.x) - kPi + kTwoPi * point.x;
  return reflectAboutHalfVector(V, x, phi, L) && L.z > 0.0;
}

double MerlSampling::pdf(const Vec3& L, const Vec3& V) const {
  if (L.z <= 0.0 || V.z <= 0.0) return 0.0;
  const HalfVector h(L, V);
  if (h.cosVH <= 0.0) return 0.0;
  const double x = h.oneMinusCosTheta;
  // The θ_h bin, settled against the stored edges so that it is the one sample() drew from.
  const double thetaH = 2.0 * std::asin(std::min(1.0, std::sqrt(0.5 * x)));
  int i = std::clamp(int(kThetaBins * std::sqrt(thetaH / (kPi / 2.0))), 0, kThetaBins - 1);
  while (i > 0 && x < xEdges_[i]) --i;
  while (i < kThetaBins - 1 && x >= xEdges_[i + 1]) ++i;
  const double dx = xEdges_[i + 1] - xEdges_[i];
  const double v = (i + std::clamp((x - xEdges_[i]) / dx, 0.0, 1.0 - 1e-9)) / kThetaBins;
  const Vec3 hv = L + V;
  const double rel = std::remainder(std::atan2(hv.y, hv.x) - std::atan2(V.y, V.x), kTwoPi);  // [−π, π]
  const double u = std::clamp((rel + kPi) / kTwoPi, 0.0, 1.0 - 1e-12);

  const ViewPosition p = viewPosition(V);
  double density = views_[p.k0].pdf(Vec2(u, v));
  if (p.t > 0.0) density = (1.0 - p.t) * density + p.t * views_[p.k1].pdf(Vec2(u, v));
  // (u, v) → H: dφ/du = 2π, dx/dv = 90 Δx, dω_H = dx dφ; then dω_L = 4⟨V,H⟩ dω_H.
  return density / (kTwoPi * kThetaBins * dx) / (4.0 * h.cosVH);
}

size_t MerlSampling::bytes() const {
  // Per view: 90 conditional rows of 64 values + 65 CDF entries, and the marginal's 90 + 91, in double.
  const size_t perView = (size_t(kThetaBins) * (2 * kPhiBins + 1) + 2 * kThetaBins + 1) * sizeof(double);
  return sizeof(*this) + views_.size() * (perView + sizeof(Distribution2D) + kThetaBins * sizeof(Distribution1D));
}

}  // namespace glossy
