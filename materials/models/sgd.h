// The Shifted Gamma Distribution microfacet model of Bagher, Soler & Holzschuch 2012  [Kd, Ks, α, p, F0, F1,
// K, Λ, c, k, θ0; every one per channel]
//   ρ = Kd/π + Ks · D · G1(L) G1(V) · F(c_d) / (π ⟨L,N⟩⟨V,N⟩)
//   D = K · exp(−t) / t^p / (π cos⁴θ_h),   t = α + tan²θ_h / α                 (the shifted gamma P22)
//   G1(v) = 1 + Λ (1 − exp(c (θ_v − θ0)^k)) where θ_v > θ0, else 1            (uncorrelated: G = G1 G1)
//   F(c_d) = F0 + (1 − F0)(1 − c_d)⁵ − F1 c_d,   c_d = ⟨V,H⟩                    (Bagher's modified Schlick)
// As bbm evaluates its `Bagher` model (bsdfmodel/bagher.h: microfacet<ndf::sgd, maskingshadowing::uncorrelated,
// fresnel::bagher, Cook>, commit 9807fb38) for the published fits of the 100 MERL materials (bagher_sgd.fit,
// materials/published-fits). K is the fitted normalisation K_{α,p} (the analytic 1/(α Γ(1−p, α)) makes
// ∫ D cos θ_h dω_h = 1; the fits' K lie within a few percent of it). [convention] the 1/(⟨L,N⟩⟨V,N⟩) of the
// Cook-Torrance form, as bbm: without it (Bagher's own ALTA plugin writes ρs D G F / π) the published lobes stay
// flat toward grazing where every other model's fit of the same material rises (docs/models.md). [choice] bbm
// does not clamp: F is negative near normal incidence for three fits (blue-fabric, white-fabric2, white-paint)
// and G1 would fall below 0 for large c; here F and each G1 are clamped at 0, so that ρ ≥ 0 — the only values
// where glossy and bbm differ. [convention] Kd is the fit's Lambertian albedo, ρ carries no cos θ_L, ρ = 0
// unless L_z > 0 and V_z > 0.
#pragma once

#include "materials/models/brdf_sample.h"
#include "materials/models/common_params.h"
#include "materials/models/half_vector.h"
#include "materials/models/schlick.h"
#include "materials/models/ward.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace glossy {

namespace sgd_sampling {

// A proposal for one channel's D cos θ_h: over t = α + tan²θ_h/α the distribution is t^(−p) e^(−t) dt on
// [α, ∞) (an upper incomplete gamma), which has no closed-form inverse. Tabulated instead: kBins bins even in
// ln t up to α + kSpan, each uniform in ln t with the bin's mass, then an exponential tail e^(−(t − t1)) beyond,
// so that every direction has a density (the estimator stays unbiased) and the density is known exactly.
struct ChannelTable {
  static constexpr int kBins = 64;
  static constexpr double kSpan = 40.0;  // e^(−40): the tail's mass, relative, is of that order
  double alpha = 1.0, y0 = 0.0, dy = 1.0, t1 = 1.0;
  std::array<double, kBins + 2> cdf{};  // cdf[kBins] .. cdf[kBins + 1]: the tail

  ChannelTable() = default;
  ChannelTable(double a, double p) : alpha(a), y0(std::log(a)), t1(a + kSpan) {
    dy = (std::log(t1) - y0) / kBins;
    // The density in y = ln t: exp((1 − p) y − e^y); Simpson over each bin (a proposal need not be exact).
    const auto g = [&](double y) { return std::exp((1.0 - p) * y - std::exp(y)); };
    std::array<double, kBins + 1> mass{};
    double total = 0.0;
    for (int i = 0; i < kBins; ++i) {
      const double a0 = y0 + i * dy;
      mass[i] = dy / 6.0 * (g(a0) + 4.0 * g(a0 + 0.5 * dy) + g(a0 + dy));
      total += mass[i];
    }
    mass[kBins] = std::exp(-p * std::log(t1) - t1);  // ∫_{t1}^∞ t^(−p) e^(−t) dt ≈ t1^(−p) e^(−t1)
    total += mass[kBins];
    // No bin empty, so that no direction is left without a density.
    for (double& m : mass) m = std::max(m, 1e-12 * total);
    double sum = 0.0;
    for (double m : mass) sum += m;
    cdf[0] = 0.0;
    for (int i = 0; i <= kBins; ++i) cdf[i + 1] = cdf[i] + mass[i] / sum;
    cdf[kBins + 1] = 1.0;
  }
  double binMass(int i) const { return cdf[i + 1] - cdf[i]; }

  // tan²θ_h for u ∈ [0, 1).
  double sampleTan2(double u) const {
    const int i = int(std::upper_bound(cdf.begin() + 1, cdf.end() - 1, u) - cdf.begin()) - 1;
    const double r = std::clamp((u - cdf[i]) / binMass(i), 0.0, 1.0);
    const double t = i == kBins ? t1 - std::log1p(-std::min(r, 1.0 - 1e-16)) : std::exp(y0 + (i + r) * dy);
    return std::max(0.0, alpha * (t - alpha));
  }
  // The density of tan²θ_h = x: that of t, times dt/dx = 1/α.
  double densityTan2(double x) const {
    const double t = alpha + x / alpha;
    if (t >= t1) return binMass(kBins) * std::exp(-(t - t1)) / alpha;
    const int i = std::clamp(int((std::log(t) - y0) / dy), 0, kBins - 1);
    return binMass(i) / (dy * t * alpha);
  }
};

}  // namespace sgd_sampling

struct Sgd {
  static constexpr std::string_view kName = "sgd";
  static constexpr std::string_view kLabel = "SGD (Bagher)";
  static constexpr std::string_view kShortLabel = "SGD";
  static constexpr std::string_view kConventions =
      "Bagher 2012 as bbm: K exp(-t)/t^p/(pi cos^4), 1/(pi cos cos), F and G1 clamped at 0";
  // Ranges around the published fits (α 1.6e-5 – 0.854, p 4.6e-15 – 1.78, F0 up to 8.48, K up to 61723, Λ up to
  // 1.5e7, c up to 1.6e109, k 5.6 – 856, θ0 −0.657 – 1.208 rad), bounded where D's peak K α^(−p) / π would
  // leave float radiance at the largest Ks.
  static constexpr ParamSpec kParams[] = {
      params::kKd,
      params::kKs,
      {"alpha", ParamKind::Rgb, {1e-6, 10.0}, "shift α of the shifted gamma distribution (R, G, B)"},
      {"p", ParamKind::Rgb, {0.0, 2.0}, "exponent p of the shifted gamma distribution (R, G, B)"},
      {"f0", ParamKind::Rgb, {0.0, 100.0}, "Fresnel term F0 (R, G, B)"},
      {"f1", ParamKind::Rgb, {-100.0, 100.0}, "Fresnel term F1 (R, G, B)"},
      {"norm", ParamKind::Rgb, {0.0, 1e8}, "normalisation K of D (R, G, B)"},
      {"lambda", ParamKind::Rgb, {0.0, 1e9}, "shadowing scale Λ (R, G, B)"},
      {"c", ParamKind::Rgb, {0.0, 1e300}, "shadowing rate c (R, G, B)"},
      {"k", ParamKind::Rgb, {0.0, 1e4}, "shadowing exponent k (R, G, B)"},
      {"theta0", ParamKind::Rgb, {-kPi / 2.0, kPi / 2.0}, "shadowing onset θ0 in radians (R, G, B)"},
  };
  static Sgd fromParams(const ParamSet& p) {
    Sgd m{p.rgb("kd"), p.rgb("ks"), p.rgb("alpha"), p.rgb("p"), p.rgb("f0"), p.rgb("f1"),
          p.rgb("norm"), p.rgb("lambda"), p.rgb("c"), p.rgb("k"), p.rgb("theta0")};
    m.prepareSampling();
    return m;
  }

  Rgb kd{0.0}, ks{0.0}, alpha{0.1}, p{0.5}, f0{0.05}, f1{0.0}, norm{1.0}, lambda{0.0}, c{0.0}, k{1.0}, theta0{0.0};

  // θ of a direction from the normal without acos's loss near the pole (bbm's form): 2 asin(|v − N| / 2).
  static double polarAngle(const Vec3& v) {
    const double d2 = v.x * v.x + v.y * v.y + (v.z - 1.0) * (v.z - 1.0);
    return 2.0 * std::asin(std::min(1.0, 0.5 * std::sqrt(d2)));
  }
  double shadowing(int ch, double theta) const {
    if (!(theta > theta0[ch]) || !(lambda[ch] > 0.0) || !(c[ch] > 0.0)) return 1.0;
    const double e = c[ch] * std::pow(theta - theta0[ch], k[ch]);
    return std::max(0.0, 1.0 - lambda[ch] * std::expm1(e));
  }
  double fresnel(int ch, double cd) const {
    return std::max(0.0, fresnelSchlick(cd, f0[ch]) - f1[ch] * cd);
  }

  Rgb eval(const Vec3& L, const Vec3& V) const {
    if (L.z <= 0.0 || V.z <= 0.0) return Rgb(0.0);
    const HalfVector h(L, V);
    Rgb rho = kd * kInvPi;
    if (h.cosVH <= 0.0) return rho;
    const double c2 = h.cosTheta * h.cosTheta, thetaL = polarAngle(L), thetaV = polarAngle(V);
    for (int ch = 0; ch < 3; ++ch) {
      if (!(ks[ch] > 0.0)) continue;
      const double t = alpha[ch] + h.tan2Theta / alpha[ch];
      const double d = norm[ch] * std::exp(-t - p[ch] * std::log(t)) / (kPi * c2 * c2);
      rho[ch] += ks[ch] * d * shadowing(ch, thetaL) * shadowing(ch, thetaV) * fresnel(ch, h.cosVH) / (kPi * L.z * V.z);
    }
    return rho;
  }

  // Sampling: one channel's D cos θ_h (sgd_sampling::ChannelTable), the channel drawn in proportion to its
  // lobe's albedo at normal incidence, Ks (4/π) |F(1)| (bbm weighs its components so), and the lobe against
  // the cosine lobe by the mean of those.
  std::array<sgd_sampling::ChannelTable, 3> tables{};
  std::array<double, 3> channelWeight{};
  double lobeAlbedo = 0.0;

  void prepareSampling() {
    double sum = 0.0;
    for (int ch = 0; ch < 3; ++ch) {
      tables[ch] = sgd_sampling::ChannelTable(alpha[ch], p[ch]);
      channelWeight[ch] = ks[ch] > 0.0 ? ks[ch] * std::max(1e-3, std::abs(f0[ch] - f1[ch])) : 0.0;
      sum += channelWeight[ch];
    }
    lobeAlbedo = 4.0 * kInvPi * sum / 3.0;
    for (double& w : channelWeight) w = sum > 0.0 ? w / sum : 0.0;
  }
  double specularProbability() const { return lobeProbability(lobeAlbedo, kd); }
  bool sampleLobe(const Vec3& V, Vec2 u, Vec3& L) const {
    // The channel whose share of [0, 1) holds u.x (the last one with a share, against rounding), then u.x
    // rescaled within that share.
    int ch = -1;
    double below = 0.0, chosenBelow = 0.0;
    for (int i = 0; i < 3; ++i) {
      if (!(channelWeight[i] > 0.0)) continue;
      ch = i, chosenBelow = below;
      if (u.x < below + channelWeight[i]) break;
      below += channelWeight[i];
    }
    if (ch < 0) return false;
    const double ux = std::clamp((u.x - chosenBelow) / channelWeight[ch], 0.0, 1.0 - 1e-16);
    const double tan2 = tables[ch].sampleTan2(ux);
    return reflectAboutHalfVector(V, ward_sampling::oneMinusCosOfTan2(tan2), 2.0 * kPi * u.y, L);
  }
  // pdf_H = p(tan²θ_h) / (π cos³θ_h) (dω_H = cos³θ_h d tan²θ_h dφ / 2), pdf_L = pdf_H / (4⟨V,H⟩).
  double lobePdf(const Vec3& L, const Vec3& V) const {
    const HalfVector h(L, V);
    if (h.cosVH <= 0.0) return 0.0;
    double density = 0.0;
    for (int ch = 0; ch < 3; ++ch)
      if (channelWeight[ch] > 0.0) density += channelWeight[ch] * tables[ch].densityTan2(h.tan2Theta);
    const double c3 = h.cosTheta * h.cosTheta * h.cosTheta;
    return density / (kPi * c3 * 4.0 * h.cosVH);
  }
  BrdfSample sample(const Vec3& V, double uLobe, Vec2 u) const { return sampleMixture(*this, V, uLobe, u); }
  double pdf(const Vec3& L, const Vec3& V) const { return mixturePdf(*this, L, V); }
};

}  // namespace glossy
