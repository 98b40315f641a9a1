// The GGX model (materials/models/ggx.h) against values computed here independently: the textbook form of
// each factor in long double (Walter et al.'s D in cos θ_h, Λ from tan θ, Fresnel as the mean of Snell's s-
// and p-reflectances), the normalisations its sampler rests on (∫ D cos θ_h = 1, ∫ G₁(V) ⟨V,H⟩⁺ D = ⟨V,N⟩),
// the head-on albedo, energy, reciprocity, and the refusal of degenerate parameters.
#include "materials/models/albedo.h"
#include "materials/models/ggx.h"
#include "materials/params/material_file.h"
#include "tests/support/test_support.h"

#include <cmath>
#include <random>

namespace glossy::test {

namespace {

using Real = long double;

Vec3 dir(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// The specular factor D G₂ F / (4 cos θ_L cos θ_V), from the textbook forms, in long double.
Real textbookLobe(const Vec3& L, const Vec3& V, Real alpha, Real eta) {
  const Real hx = Real(L.x) + V.x, hy = Real(L.y) + V.y, hz = Real(L.z) + V.z;
  const Real len = std::sqrt(hx * hx + hy * hy + hz * hz);
  const Real cosH = hz / len, cosVH = (V.x * hx + V.y * hy + V.z * hz) / len;
  const Real a2 = alpha * alpha, k = cosH * cosH * (a2 - 1) + 1;
  const Real d = a2 / (3.14159265358979323846264338327950288L * k * k);
  const auto lambda = [&](Real c) {
    const Real tan2 = (1 - c * c) / (c * c);
    return (std::sqrt(1 + a2 * tan2) - 1) / 2;
  };
  const Real g2 = 1 / (1 + lambda(L.z) + lambda(V.z));
  const Real sinT = std::sqrt(1 - cosVH * cosVH) / eta, cosT = std::sqrt(1 - sinT * sinT);
  const Real rs = (cosVH - eta * cosT) / (cosVH + eta * cosT), rp = (eta * cosVH - cosT) / (eta * cosVH + cosT);
  const Real f = (rs * rs + rp * rp) / 2;
  return d * g2 * f / (4 * Real(L.z) * V.z);
}

}  // namespace

TEST(GgxModel, EqualsTheTextbookEquationComputedInLongDouble) {
  struct Case {
    double alpha, eta, thetaL, phiL, thetaV, phiV;
  };
  const Case cases[] = {
      {0.02, 1.5, 0.3, kPi + 0.001, 0.3, 0.0},   // sharp, 1 mrad from the mirror direction
      {0.02, 1.5, 0.0, 0.0, 0.0, 0.0},           // sharp, head-on peak
      {0.02, 2.5, 1.4, kPi + 0.02, 1.41, 0.0},   // sharp, grazing
      {0.5, 1.5, 0.7, 2.0, 0.2, 0.5},            // broad
      {0.5, 1.7, 1.5, kPi, 1.45, 0.0},           // broad, grazing mirror pair
      {0.5, 99.999, 1.2, 0.3, 1.3, 1.9},         // broad, near-conductor η, back-scattering
      {1.7, 1.3, 0.4, 1.0, 1.0, 3.0},            // α > 1
  };
  for (const Case& c : cases) {
    const Vec3 L = dir(c.thetaL, c.phiL), V = dir(c.thetaV, c.phiV);
    const Rgb kd(0.1, 0.2, 0.3), ks(0.5, 0.7, 1.1);
    const Rgb f = Ggx{kd, ks, c.alpha, c.eta}.eval(L, V);
    const Real lobe = textbookLobe(L, V, c.alpha, c.eta);
    for (int k = 0; k < 3; ++k) {
      const Real expected = Real(kd[k]) / 3.14159265358979323846264338327950288L + ks[k] * lobe;
      EXPECT_NEAR(f[k] / double(expected), 1.0, 1e-12) << "α " << c.alpha << " θL " << c.thetaL << " θV " << c.thetaV;
    }
  }
  // Below the horizon: zero.
  const Ggx below{Rgb(0.1), Rgb(1.0), 0.3, 1.5};
  EXPECT_EQ(below.eval(dir(0.3, 0.0), dir(1.7, 0.0)).r, 0.0);
}

TEST(GgxModel, IsReciprocal) {
  const Ggx ggx{Rgb(0.1), Rgb(0.8), 0.15, 1.6};
  for (double tl : {0.0, 0.4, 1.1, 1.55})
    for (double tv : {0.1, 0.8, 1.5})
      for (double phi : {0.0, 1.0, kPi}) {
        const Vec3 L = dir(tl, phi), V = dir(tv, 0.3);
        EXPECT_NEAR(ggx.eval(L, V).r, ggx.eval(V, L).r, 1e-13 * ggx.eval(L, V).r) << tl << " " << tv << " " << phi;
      }
}

// The two integrals of the microfacet theory the sampler's pdf rests on, by the midpoint rule over H in
// (x = 1 − cos θ_h, φ_h), with x on a geometric ladder so that a sharp lobe gets nodes: D is a density of
// projected facet area, and the facets V sees (G₁(V) ⟨V,H⟩⁺ D) project to ⟨V,N⟩, which holds only when Λ
// belongs to D. Together they make the visible-normal density integrate to 1.
TEST(GgxModel, DistributionAndMaskingAreNormalised) {
  for (double alpha : {0.02, 0.5, 1.5}) {
    const double a2 = alpha * alpha;
    for (double thetaV : {0.0, 1.0, 1.45}) {
      const Vec3 V = dir(thetaV, 0.4);
      const double g1 = 1.0 / (1.0 + Ggx::lambda(a2, V.z));
      double projected = 0.0, visible = 0.0;
      const int nx = 4000, nphi = 256;
      const double ratio = std::pow(1e9, 1.0 / nx);  // x from 1e-9 to 1
      for (int i = 0; i < nx; ++i) {
        const double x0 = 1e-9 * std::pow(ratio, i), x1 = x0 * ratio, x = std::sqrt(x0 * x1), dx = x1 - x0;
        const double cosH = 1.0 - x, sinH = std::sqrt(x * (2.0 - x)), tan2 = sinH * sinH / (cosH * cosH);
        const double d = Ggx::distribution(a2, tan2);
        projected += d * cosH * 2.0 * kPi * dx;
        for (int j = 0; j < nphi; ++j) {
          const double phi = 2.0 * kPi * (j + 0.5) / nphi;
          const Vec3 H(sinH * std::cos(phi), sinH * std::sin(phi), cosH);
          visible += g1 * std::max(0.0, glm::dot(V, H)) * d * dx * (2.0 * kPi / nphi);
        }
      }
      EXPECT_NEAR(projected, 1.0, 2e-3) << "α " << alpha;
      EXPECT_NEAR(visible / V.z, 1.0, 2e-3) << "α " << alpha << " θV " << thetaV;
    }
  }
}

TEST(GgxModel, ReflectsAtMostWhatArrives) {
  // Head-on, H at θ_h sends L to 2θ_h and dω_L = 4⟨V,H⟩ dω_H, so the lobe's albedo is the 1D integral
  // 2π ∫₀^{π/4} D(θ) cos θ sin θ F(cos θ) / (1 + Λ(2θ)) dθ (textbook forms, midpoint rule, long double),
  // against albedoAtNormalIncidence's quadrature over L of eval().
  for (double alpha : {0.02, 0.1, 0.5, 1.0}) {
    const Real a2 = Real(alpha) * alpha, pi = 3.14159265358979323846264338327950288L, eta = 1.5;
    Real sum = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      const Real t = (i + 0.5L) / n * pi / 4, c = std::cos(t), k = c * c * (a2 - 1) + 1;
      const Real tan2L = std::tan(2 * t) * std::tan(2 * t), lambdaL = (std::sqrt(1 + a2 * tan2L) - 1) / 2;
      const Real sinT = std::sqrt(1 - c * c) / eta, cosT = std::sqrt(1 - sinT * sinT);
      const Real rs = (c - eta * cosT) / (c + eta * cosT), rp = (eta * c - cosT) / (eta * c + cosT);
      sum += a2 / (pi * k * k) * c * std::sin(t) * (rs * rs + rp * rp) / 2 / (1 + lambdaL);
    }
    const double expected = double(2 * pi * sum * (pi / 4) / n);
    const double albedo = albedoAtNormalIncidence(Ggx{Rgb(0.0), Rgb(1.0), alpha, double(eta)}).r;
    EXPECT_NEAR(albedo, expected, 1e-4 * expected) << "α " << alpha;
  }
  // At any incidence and F ≈ 1 (η = 1e3), by Monte Carlo through the sampler (weights = ρ cos / pdf): at most
  // 1, falling with roughness as single scattering loses the light facets send below the horizon or into
  // each other (0.69 head-on at α = 0.5: a fifth of its normals lie beyond 45°).
  for (double thetaV : {0.0, 0.8, 1.5}) {
    double previous = 1.0;
    for (double alpha : {0.02, 0.5, 1.0}) {
      const Ggx ggx{Rgb(0.0), Rgb(1.0), alpha, 1e3};
      const Vec3 V = dir(thetaV, 0.0);
      const int n = 200000;
      double sum = 0.0;
      std::mt19937_64 rng(7);
      std::uniform_real_distribution<double> u(0.0, 1.0);
      for (int k = 0; k < n; ++k) {
        const BrdfSample s = ggx.sample(V, u(rng), Vec2(u(rng), u(rng)));
        if (s.valid()) sum += s.weight.r;
      }
      EXPECT_LE(sum / n, previous) << "α " << alpha << " θV " << thetaV;
      EXPECT_GT(sum / n, 0.2) << "α " << alpha << " θV " << thetaV;
      previous = sum / n;
    }
  }
}

TEST(GgxModel, DegenerateRoughnessIsRefusedNamingFileAndKey) {
  TempDir dir;
  const std::filesystem::path file = dir / "ggx.toml";
  for (const std::string bad : {"alpha = 0.0", "alpha = 5e-5", "alpha = -0.1", "alpha = nan", "alpha = 11.0"}) {
    writeText(file, "name = \"ggx\"\n\n[[fit]]\nmodel = \"ggx\"\nmetric = \"E2\"\nkd = [0.1, 0.1, 0.1]\n"
                    "ks = [0.5, 0.5, 0.5]\n" + bad + "\neta = 1.5\n");
    const std::string message = expectInputError([&] { loadMaterialFile(file); });
    EXPECT_NE(message.find(file.string() + ":8"), std::string::npos) << message;
    EXPECT_NE(message.find("'alpha'"), std::string::npos) << message;
    expectOneLineError(runGlossy({"eval", "--material", file.string(), "--fit", "ggx:E2"}, "0,0,1,0,0,1\n"), file.string());
  }
}

}  // namespace glossy::test
