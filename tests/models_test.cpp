// Properties of the models that hold for every fit of the library: reciprocity, zero below the horizon,
// finite values at grazing angles and exactly at the mirror peak, the numerical guards, and the interim
// sampler's pdf/weight consistency.
#include "materials/models/brdf.h"
#include "materials/models/fresnel.h"
#include "materials/models/half_vector.h"
#include "materials/params/material_file.h"
#include "tests/support/test_support.h"

#include <cmath>
#include <random>
#include <variant>
#include <vector>

namespace glossy::test {

namespace {

std::vector<std::pair<std::string, Brdf>> libraryBrdfs() {
  std::vector<std::pair<std::string, Brdf>> all;
  for (const auto& e : std::filesystem::directory_iterator(materialsDir())) {
    if (e.path().extension() != ".toml") continue;
    const MaterialFile m = loadMaterialFile(e.path());
    for (const Fit& f : m.fits) all.emplace_back(m.name + " " + f.id.str(), makeBrdf(f));
  }
  return all;
}

Vec3 dir(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

// An SGD lobe with Bagher's Fresnel F = F0 + (1 − F0)(1 − c)⁵ of F0 = 0.9 (F1 = 0) and shadowing of onset θ0
// (Λ = 1, c = 1, k = 2): the shape parameters named, the rest fixed.
Brdf sgdOf(Rgb kd, Rgb ks, Rgb alpha, Rgb p, Rgb norm, Rgb f1, Rgb theta0) {
  ParamSet params;
  params.set("kd", kd), params.set("ks", ks), params.set("alpha", alpha), params.set("p", p), params.set("norm", norm);
  params.set("f0", Rgb(0.9)), params.set("f1", f1), params.set("lambda", Rgb(1.0)), params.set("c", Rgb(1.0));
  params.set("k", Rgb(2.0)), params.set("theta0", theta0);
  return Sgd::fromParams(params);
}

bool finiteNonNegative(const Rgb& c) {
  return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b) && c.r >= 0 && c.g >= 0 && c.b >= 0;
}

}  // namespace

TEST(Fresnel, LimitsAndNormalIncidence) {
  for (double eta : {1.0001, 1.5, 2.236525, 9.79957, 99.999413}) {
    const double f0 = (eta - 1) / (eta + 1);
    EXPECT_NEAR(fresnelCookTorrance(1.0, eta), f0 * f0, 1e-15) << eta;
    EXPECT_NEAR(fresnelAtNormalIncidence(eta), fresnelCookTorrance(1.0, eta), 1e-15) << eta;
    EXPECT_NEAR(fresnelCookTorrance(0.0, eta), 1.0, 1e-15) << eta;
    // Against the textbook form: the mean of the s and p reflectances with Snell's law.
    for (double c = 0.0; c <= 1.0; c += 1.0 / 64) {
      const double ct = std::sqrt(1.0 - (1.0 - c * c) / (eta * eta));
      const double rs = (c - eta * ct) / (c + eta * ct), rp = (eta * c - ct) / (eta * c + ct);
      EXPECT_NEAR(fresnelCookTorrance(c, eta), 0.5 * (rs * rs + rp * rp), 1e-13) << "eta " << eta << " c " << c;
    }
  }
}

TEST(HalfVector, OneMinusCosineWithoutCancellation) {
  // A pair 1e-7 rad off the mirror direction: 1 − cos θ_h ~ 1e-15, where the subtraction keeps no digits.
  for (double offset : {1e-3, 1e-5, 1e-7, 1e-9}) {
    const double thetaV = 0.7;
    const Vec3 V = dir(thetaV, 0.0), L = dir(thetaV + offset, kPi);
    const HalfVector h(L, V);
    const long double th = offset / 2.0L;  // θ_h is half the angular offset for an in-plane pair
    const long double exact = 2.0L * std::sin(th / 2.0L) * std::sin(th / 2.0L);
    EXPECT_NEAR(h.oneMinusCosTheta, static_cast<double>(exact), 1e-6 * static_cast<double>(exact)) << offset;
    EXPECT_NEAR(h.tan2Theta, static_cast<double>(std::tan(th) * std::tan(th)), 1e-6 * static_cast<double>(std::tan(th) * std::tan(th)));
  }
}

TEST(Library, EveryFitIsReciprocalFiniteAndZeroBelowTheHorizon) {
  const auto brdfs = libraryBrdfs();
  // 600 published by Löw et al., glossy's 600 refits beside them, 6 GGX E2 fits, and Ngan et al.'s fits of 86
  // materials, one per bbm ngan_*.fit file in materials/published-fits, and Bagher et al.'s of all 100.
  size_t nganModels = 0;
  for (const auto& e : std::filesystem::directory_iterator(sourceDir() / "materials/published-fits"))
    nganModels += e.path().extension() == ".fit" && e.path().filename().string().starts_with("ngan_");
  ASSERT_EQ(brdfs.size(), 1206u + 86u * nganModels + 100u);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const auto& [name, brdf] : brdfs) {
    for (int i = 0; i < 64; ++i) {
      const Vec3 L = dir(std::acos(u(rng)), 2 * kPi * u(rng)), V = dir(std::acos(u(rng)), 2 * kPi * u(rng));
      const Rgb a = eval(brdf, L, V), b = eval(brdf, V, L);
      ASSERT_TRUE(finiteNonNegative(a)) << name;
      for (int c = 0; c < 3; ++c) ASSERT_NEAR(a[c], b[c], 1e-12 * std::max(1.0, std::abs(a[c]))) << name;
      EXPECT_EQ(eval(brdf, Vec3(L.x, L.y, -L.z), V), Rgb(0.0)) << name;
      EXPECT_EQ(eval(brdf, L, Vec3(V.x, V.y, -V.z)), Rgb(0.0)) << name;
    }
    // The mirror peak, grazing pairs, and the horizon itself.
    for (double theta : {0.0, 1e-8, 0.5, 1.5, 1.5707, kPi / 2 - 1e-9}) {
      const Vec3 V = dir(theta, 0.3), mirror(-V.x, -V.y, V.z);
      ASSERT_TRUE(finiteNonNegative(eval(brdf, mirror, V))) << name << " θ=" << theta;
      ASSERT_TRUE(finiteNonNegative(eval(brdf, dir(kPi / 2 - 1e-12, 2.0), V))) << name;
    }
    EXPECT_EQ(eval(brdf, Vec3(std::cos(1.0), std::sin(1.0), 0.0), dir(0.3, 0.0)), Rgb(0.0)) << name << ": L on the horizon";
  }
}

TEST(Smooth, FresnelOptionsAgreeAtTheMirrorConfiguration) {
  Smooth projected{Rgb(0.0), Rgb(1.0), 100.0, 1.0, 1.5, false};
  Smooth vh = projected;
  vh.fresnelVH = true;
  for (double theta : {0.1, 0.6, 1.2}) {
    const Vec3 V = dir(theta, 0.4), L(-V.x, -V.y, V.z);
    EXPECT_NEAR(projected.eval(L, V).r, vh.eval(L, V).r, 1e-12);
  }
  // …and differ off the peak, where the convention matters (B = 0 leaves F alone).
  projected.b = vh.b = 0.0;
  const Vec3 V = dir(1.2, 0.0), L = dir(0.4, 2.0);
  EXPECT_GT(std::abs(projected.eval(L, V).r / vh.eval(L, V).r - 1.0), 0.01);
}

TEST(Sampling, PdfIsTheDensitySampleDrawsAndWeightIsRhoCosOverPdf) {
  const auto brdfs = libraryBrdfs();
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (size_t k = 0; k < brdfs.size(); k += 7) {
    const auto& [name, brdf] = brdfs[k];
    for (double theta : {0.0, 0.7, 1.4}) {
      const Vec3 V = dir(theta, 1.0);
      for (int i = 0; i < 16; ++i) {
        const BrdfSample s = sample(brdf, V, u(rng), Vec2(u(rng), u(rng)));
        if (!s.valid()) continue;
        EXPECT_NEAR(s.pdf, pdf(brdf, s.L, V), 1e-12 * s.pdf) << name;
        const Rgb expected = eval(brdf, s.L, V) * (s.L.z / s.pdf);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.weight[c], expected[c], 1e-9 * std::max(1.0, expected[c])) << name;
      }
    }
  }
}

// The batch forms the path tracer calls (sampleBatch, evalPdfBatch): lane by lane what sample and evalPdf
// return, for every fit of the library (the sharpest lobes included), 1 lane to more than two batches of
// them, both lobes of the mixture, V at 89.7° and V and L below the horizon, and the ends of the unit
// square. Cook-Torrance's and Microfacet's one-lane forms are the plain formulas of their headers (libm)
// and their batch forms are kernels over lanes (libmvec, at most 4 ulp from libm per call), so the two
// cannot share every bit: they must agree to 1e-12 relative (the worst seen is 3e-14, printed).
TEST(Sampling, BatchFormsEqualTheOneLaneForms) {
  const auto brdfs = libraryBrdfs();
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  double worst = 0.0;
  const auto close = [&](double a, double b) {
    const double d = std::abs(a - b) / std::max(1.0, std::abs(b));
    worst = std::max(worst, d);
    return d <= 1e-12;
  };
  int cookTorrance = 0, microfacet = 0, validSamples = 0;
  for (const auto& [name, brdf] : brdfs) {
    cookTorrance += brdf.as<CookTorrance>() != nullptr;
    microfacet += brdf.as<Microfacet>() != nullptr;
    for (int n : {1, 3, 4, 17, kMaxBatchLanes, 2 * kMaxBatchLanes + 5}) {
      std::vector<Vec3> V(n), L(n);
      std::vector<double> uLobe(n);
      std::vector<Vec2> u(n);
      for (int k = 0; k < n; ++k) {
        V[k] = k % 11 == 5 ? dir(1.7, 0.4) : k % 7 == 3 ? dir(1.565, 2 * kPi * uni(rng)) : dir(1.5 * uni(rng), 2 * kPi * uni(rng));
        L[k] = k % 13 == 7 ? dir(1.6, 2.0) : dir(1.5 * uni(rng), 2 * kPi * uni(rng));
        uLobe[k] = uni(rng);
        u[k] = k % 9 == 2 ? Vec2(0.0, 0.0) : k % 9 == 4 ? Vec2(1.0 - 0x1p-53, 0.5) : Vec2(uni(rng), uni(rng));
      }
      std::vector<BrdfSample> s(n);
      std::vector<BrdfValue> v(n);
      sampleBatch(brdf, V.data(), uLobe.data(), u.data(), s.data(), n);
      evalPdfBatch(brdf, L.data(), V.data(), v.data(), n);
      for (int k = 0; k < n; ++k) {
        const BrdfSample one = sample(brdf, V[k], uLobe[k], u[k]);
        ASSERT_EQ(s[k].valid(), one.valid()) << name << " lane " << k << " of " << n;
        validSamples += one.valid();
        if (one.valid()) {
          // The direction, then the value and density at the batch's own direction: at grazing angles
          // a last-bit difference in L moves a sharp lobe's density by more than 1e-12 relative.
          for (int c = 0; c < 3; ++c) ASSERT_TRUE(close(s[k].L[c], one.L[c])) << name << ": L " << s[k].L[c] << " vs " << one.L[c];
          const BrdfSample there = mixtureSample(s[k].L, evalPdf(brdf, s[k].L, V[k]));
          ASSERT_TRUE(close(s[k].pdf, there.pdf)) << name << ": pdf " << s[k].pdf << " vs " << there.pdf;
          for (int c = 0; c < 3; ++c) ASSERT_TRUE(close(s[k].weight[c], there.weight[c])) << name << ": weight";
        }
        const BrdfValue value = evalPdf(brdf, L[k], V[k]);
        ASSERT_TRUE(close(v[k].pdf, value.pdf)) << name << ": evalPdf's pdf " << v[k].pdf << " vs " << value.pdf;
        for (int c = 0; c < 3; ++c) ASSERT_TRUE(close(v[k].f[c], value.f[c])) << name << ": evalPdf's f";
      }
    }
  }
  EXPECT_GT(cookTorrance, 0) << "no Cook-Torrance fit in the library: its batch forms went untested";
  EXPECT_GT(microfacet, 0) << "no Microfacet fit in the library: its batch forms went untested";
  EXPECT_GT(validSamples, 1000);
  std::printf("worst relative difference %.3g\n", worst);
}

TEST(Sampling, PdfIntegratesToTheSamplersAcceptanceProbability) {
  // Lobes broad enough for a midpoint rule in (cos θ, φ); the sampler may reject (a reflected direction
  // below the horizon, Smooth's points outside the unit disk), and the pdf is not renormalised, so its
  // integral is the acceptance probability: ≤ 1, and equal to the fraction of valid samples.
  const std::pair<const char*, Brdf> cases[] = {
      {"cook-torrance m=0.3", CookTorrance{Rgb(0.1), Rgb(0.2), 0.3, 1.5}},
      {"ashikhmin-shirley n=20", AshikhminShirley{Rgb(0.05), Rgb(0.5), 20.0, 1.8}},
      {"microfacet C=1.5", Microfacet{Rgb(0.05), Rgb(2.0), 50.0, 1.5, 1.5}},
      {"microfacet C=1", Microfacet{Rgb(0.05), Rgb(2.0), 50.0, 1.0, 1.5}},
      {"smooth C=0.5", Smooth{Rgb(0.05), Rgb(2.0), 10.0, 0.5, 1.5, false}},
      {"lambertian", Lambertian{Rgb(0.5)}},
      {"ggx alpha=0.5", Ggx{Rgb(0.05), Rgb(0.5), 0.5, 1.5}},
      {"ward alpha=0.3", Ward{Rgb(0.05), Rgb(0.5), 0.3}},
      {"ward-duer alpha=0.3", WardDuer{Rgb(0.05), Rgb(0.5), 0.3}},
      {"blinn-phong n=20", BlinnPhong{Rgb(0.05), Rgb(0.2), 20.0}},
      {"lafortune n=5", Lafortune{Rgb(0.05), Rgb(0.5), -0.6, 0.4, 5.0}},
      {"ngan-ashikhmin-shirley n=20", NganAshikhminShirley{Rgb(0.05), Rgb(0.5), 0.3, 20.0}},
      {"ngan-cook-torrance m=0.3", NganCookTorrance{Rgb(0.1), Rgb(0.5), 0.3, 0.3}},
      {"sgd alpha=0.05..0.3", sgdOf(Rgb(0.1), Rgb(0.5), Rgb(0.05, 0.1, 0.3), Rgb(0.5, 0.2, 1.2), Rgb(10.0), Rgb(0.02), Rgb(0.0))},
  };
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  for (const auto& [name, brdf] : cases)
    for (double thetaV : {0.0, 0.9, 1.45}) {
      const Vec3 V = dir(thetaV, 0.3);
      const int n = 500;
      double integral = 0.0;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < 2 * n; ++j) {
          const double mu = (i + 0.5) / n, phi = 2 * kPi * (j + 0.5) / (2 * n);
          integral += pdf(brdf, dir(std::acos(mu), phi), V) * (1.0 / n) * (kPi / n);
        }
      const int samples = 400000;
      int valid = 0;
      for (int k = 0; k < samples; ++k) valid += sample(brdf, V, uni(rng), Vec2(uni(rng), uni(rng))).valid();
      const double acceptance = double(valid) / samples;
      EXPECT_LE(integral, 1.0 + 2e-3) << name << " θv=" << thetaV;
      EXPECT_NEAR(integral, acceptance, 3e-3) << name << " θv=" << thetaV;
    }
  EXPECT_EQ(pdf(Brdf(CookTorrance{Rgb(0.1), Rgb(0.2), 0.3, 1.5}), dir(0.3, 0.0), dir(0.3, 0.0) * Vec3(1, 1, -1)), 0.0)
      << "no density for V below the horizon";
}

TEST(Sampling, NoNonFiniteSampleAtTheEndsOfTheUnitSquareForTheMostExtremeFits) {
  const Brdf extreme[] = {
      AshikhminShirley{Rgb(0.0), Rgb(1.0), 6.2e5, 99.999}, Microfacet{Rgb(0.0), Rgb(1e3), 8.1e6, 0.014, 1.5},
      Smooth{Rgb(0.0), Rgb(1e3), 8.1e6, 0.014, 1.5, false}, CookTorrance{Rgb(0.0), Rgb(1.0), 0.0018, 99.999},
      Microfacet{Rgb(0.1), Rgb(1.0), 0.0, 1.0, 1.5}, Smooth{Rgb(0.1), Rgb(1.0), 0.0, 2.0, 1.5, false},
      Ward{Rgb(0.0), Rgb(1.0), 1e-4}, Ward{Rgb(0.1), Rgb(1.0), 10.0},
      WardDuer{Rgb(0.0), Rgb(1.0), 1e-4},
      BlinnPhong{Rgb(0.0), Rgb(1.0), 1e8},
      Lafortune{Rgb(0.0), Rgb(1.0), -0.577, 0.577, 1e8}, Lafortune{Rgb(0.1), Rgb(1.0), -0.707, 1e-12, 0.0},
      NganAshikhminShirley{Rgb(0.0), Rgb(1.0), 0.999, 1e8},
      NganCookTorrance{Rgb(0.0), Rgb(1.0), 1.0, 1e-4},
      sgdOf(Rgb(0.0), Rgb(1e6), Rgb(1e-6), Rgb(2.0), Rgb(1e8), Rgb(100.0), Rgb(-kPi / 2.0)),
      sgdOf(Rgb(0.1), Rgb(1.0), Rgb(10.0), Rgb(0.0), Rgb(1e-3), Rgb(0.0), Rgb(kPi / 2.0)),
  };
  const double ends[] = {0.0, 1e-300, 1e-17, 0.5, 1.0 - 1e-16, std::nextafter(1.0, 0.0)};
  for (const Brdf& brdf : extreme)
    for (double thetaV : {0.0, 1e-6, 0.7, 1.5707})
      for (double a : ends)
        for (double b : ends)
          for (double lobe : {0.0, 0.999}) {
            const BrdfSample s = sample(brdf, dir(thetaV, 0.2), lobe, Vec2(a, b));
            if (!s.valid()) continue;
            ASSERT_TRUE(std::isfinite(s.pdf) && std::isfinite(s.L.x) && std::isfinite(s.L.z));
            ASSERT_TRUE(finiteNonNegative(s.weight)) << a << " " << b;
          }
}

}  // namespace glossy::test
