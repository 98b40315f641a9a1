// χ² proof of every model's sampler: sample() draws from exactly the density pdf() returns.
//
// The family: all 42 fits of the six supplement materials (36 published, glossy's 6 GGX E2) and the most extreme published fits of the
// library (largest n, largest B, smallest C, smallest and largest m, η = 99.999), each at four view angles
// up to 82°, plus Lambertian, GGX at α = 0.02 and 0.5 (ggxChi2Fits) and the sharpest and broadest published
// fits of each model of Ngan et al. 2005 (publishedLobeChi2Fits). 10⁶ samples per test on a grid of cells that follows the lobe
// (tests/support/chi2.h); family-wise significance 0.01 with Šidák's correction, over these and the
// measured sampler's tests (tests/measured_sampling_test.cpp). Negative controls show the
// test has the power to reject samplers that are 1–3 % off. The same test over every fit of the library
// runs as the `sweep` label (tests/sweep/).
#include "tests/support/chi2.h"
#include "tests/support/sampling_cases.h"
#include "tests/support/test_support.h"

#include <cmath>
#include <sstream>

namespace glossy::test {

namespace {

constexpr long kSamples = 1000000;

const std::vector<SamplingCase>& family() { return analyticChi2Family(); }
double familyAlpha() { return chi2TestAlpha(); }

class Chi2 : public ::testing::TestWithParam<SamplingCase> {};

}  // namespace

TEST(Chi2Family, CoversTheSupplementAndAtLeastTwentyExtremeFitsAtFourViewAngles) {
  EXPECT_EQ(supplementFits().size(), 42u);
  EXPECT_GE(extremeFits().size(), 20u);
  std::string names;
  for (const LibraryFit& f : extremeFits()) names += (names.empty() ? "" : ", ") + f.name;
  RecordProperty("extremeFits", names);
  EXPECT_EQ(family().size(), (supplementFits().size() + extremeFits().size() + 1 + ggxChi2Fits().size() + publishedLobeChi2Fits().size()) * kViewAngles.size());
  RecordProperty("familySize", int(family().size()) + kMeasuredChi2Tests);
  RecordProperty("perTestAlpha", std::to_string(familyAlpha()));
}

TEST(Chi2Statistics, SurvivalFunctionMatchesTabulatedQuantiles) {
  // Upper quantiles of χ²(dof) from standard tables.
  EXPECT_NEAR(chi2Survival(3.841459, 1), 0.05, 1e-6);
  EXPECT_NEAR(chi2Survival(6.634897, 1), 0.01, 1e-7);
  EXPECT_NEAR(chi2Survival(23.209251, 10), 0.01, 1e-7);
  EXPECT_NEAR(chi2Survival(1.610308, 5), 0.90, 1e-6);
  EXPECT_NEAR(chi2Survival(1106.969, 1000), 0.01, 1e-5);
  EXPECT_NEAR(chi2Survival(1000.0 - 0.6667, 1000), 0.5, 5e-3);
  EXPECT_NEAR(sidakAlpha(0.01, 1), 0.01, 1e-15);
  EXPECT_NEAR(sidakAlpha(0.01, 200), 5.02509e-5, 1e-9);
}

TEST_P(Chi2, SampleDrawsFromExactlyThePdf) {
  const SamplingCase& c = GetParam();
  // A seed of its own per case: Šidák's correction assumes independent tests.
  const SamplingCheck check = checkSampler(c, kSamples, c.seed(), familyAlpha());
  RecordProperty("pValue", std::to_string(check.chi2.pValue));
  RecordProperty("dof", check.chi2.degreesOfFreedom);
  RecordProperty("pdfIntegral", std::to_string(check.chi2.pdfIntegral));
  EXPECT_TRUE(check.chi2.passed) << c.label() << ": " << check.chi2.message;
  EXPECT_EQ(check.weightMismatches, 0) << c.label() << ": weight ≠ ρ cos θ_L / pdf or pdf(L) ≠ sample.pdf";
  // The pdf integrates to the sampler's acceptance probability: ≤ 1, and 1 where nothing is rejected.
  const double p = check.chi2.pdfIntegral;
  EXPECT_LE(p, 1.0 + 1e-7) << c.label();
  const double sigma = std::sqrt(std::max(p * (1.0 - p), 1.0 / kSamples) / kSamples);
  EXPECT_NEAR(check.chi2.acceptance, p, 5.0 * sigma + 1e-7) << c.label() << ": " << check.chi2.message;
  if (check.chi2.acceptance == 1.0) {
    EXPECT_NEAR(p, 1.0, 1e-6) << c.label() << " rejects nothing";
  }
}

INSTANTIATE_TEST_SUITE_P(Family, Chi2, ::testing::ValuesIn(family()),
                         [](const auto& info) { return info.param.testName(); });

// Negative controls: samplers that are slightly wrong must be rejected at the family's significance, or the
// family proves nothing. Each draws from a perturbed copy of the model and claims the original's pdf.
namespace {

struct Perturbed {
  const char* name;
  Brdf claimed, drawn;
  double thetaV;
};

Chi2Result perturbedChi2(const Perturbed& p, double pdfScale = 1.0) {
  const Vec3 V = viewDirection(p.thetaV);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const DirectionSampler draw = [&](std::mt19937_64& rng) -> std::optional<Vec3> {
    const double lobe = u(rng), u1 = u(rng), u2 = u(rng);
    const BrdfSample s = sample(p.drawn, V, lobe, Vec2(u1, u2));
    if (!s.valid()) return std::nullopt;
    return s.L;
  };
  const DirectionPdf density = [&](const Vec3& L) { return pdfScale * pdf(p.claimed, L, V); };
  return chi2Test(draw, density, gridFor(p.claimed, V), kSamples, 99, familyAlpha());
}

}  // namespace

TEST(Chi2Power, RejectsSamplersOneToThreePercentOff) {
  const double deg = kPi / 180.0;
  const Perturbed cases[] = {
      {"AS n=6.2e5 drawn with n·1.03", AshikhminShirley{Rgb(0.0), Rgb(1.0), 6.2e5, 1.5},
       AshikhminShirley{Rgb(0.0), Rgb(1.0), 6.2e5 * 1.03, 1.5}, 35 * deg},
      {"AS n=5000 drawn with n·1.04", AshikhminShirley{Rgb(0.05), Rgb(0.5), 5000.0, 1.5},
       AshikhminShirley{Rgb(0.05), Rgb(0.5), 5000.0 * 1.04, 1.5}, 65 * deg},
      {"CT m=0.0018 drawn with m·1.01", CookTorrance{Rgb(0.0), Rgb(1.0), 0.0018, 99.999},
       CookTorrance{Rgb(0.0), Rgb(1.0), 0.0018 * 1.01, 99.999}, 0.0},
      {"Microfacet B=8.1e6 C=0.5 drawn with C·1.02", Microfacet{Rgb(0.0), Rgb(1.0), 8.1e6, 0.5, 1.5},
       Microfacet{Rgb(0.0), Rgb(1.0), 8.1e6, 0.5 * 1.02, 1.5}, 82 * deg},
      {"Smooth B=1e4 C=2 drawn with the C = 1 scheme's lobe", Smooth{Rgb(0.0), Rgb(1.0), 1e4, 2.0, 1.5, false},
       Smooth{Rgb(0.0), Rgb(1.0), 1e4, 1.0, 1.5, false}, 35 * deg},
      {"Smooth B=1e4 C=1.5 drawn with B·1.04", Smooth{Rgb(0.0), Rgb(1.0), 1e4, 1.5, 1.5, false},
       Smooth{Rgb(0.0), Rgb(1.0), 1e4 * 1.04, 1.5, 1.5, false}, 65 * deg},
      {"GGX α=0.02 drawn with α·1.02", Ggx{Rgb(0.0), Rgb(1.0), 0.02, 1.5}, Ggx{Rgb(0.0), Rgb(1.0), 0.02 * 1.02, 1.5},
       82 * deg},
      {"GGX α=0.5 drawn with α·1.03", Ggx{Rgb(0.0), Rgb(1.0), 0.5, 1.5}, Ggx{Rgb(0.0), Rgb(1.0), 0.5 * 1.03, 1.5}, 0.0},
      {"Ward α=0.00576 drawn with α·1.02", Ward{Rgb(0.0), Rgb(1.0), 0.00576}, Ward{Rgb(0.0), Rgb(1.0), 0.00576 * 1.02}, 65 * deg},
      {"Blinn-Phong n=1.21e5 drawn with n·1.03", BlinnPhong{Rgb(0.0), Rgb(1.0), 1.21e5}, BlinnPhong{Rgb(0.0), Rgb(1.0), 1.21e5 * 1.03}, 35 * deg},
      {"Lafortune n=1.66e4 drawn with n·1.03", Lafortune{Rgb(0.0), Rgb(1.0), -0.577, 0.577, 16600.0},
       Lafortune{Rgb(0.0), Rgb(1.0), -0.577, 0.577, 16600.0 * 1.03}, 35 * deg},
      {"Lafortune Cz=0.4 drawn with Cz·1.03", Lafortune{Rgb(0.0), Rgb(1.0), -0.6, 0.4, 50.0},
       Lafortune{Rgb(0.0), Rgb(1.0), -0.6, 0.4 * 1.03, 50.0}, 65 * deg},
      {"lobe choice 0.023 off (Kd·1.1 in the mixture weight)", CookTorrance{Rgb(0.2), Rgb(1.0), 0.1, 1.5},
       CookTorrance{Rgb(0.22), Rgb(1.0), 0.1, 1.5}, 35 * deg},
  };
  for (const Perturbed& p : cases) {
    const Chi2Result r = perturbedChi2(p);
    EXPECT_FALSE(r.passed) << p.name << " passed: " << r.message;
    RecordProperty(p.name, std::to_string(r.pValue));
  }
  // And the unperturbed sampler passes on the same grid and seed.
  const Perturbed exact{"exact", cases[0].claimed, cases[0].claimed, cases[0].thetaV};
  EXPECT_TRUE(perturbedChi2(exact).passed);
}

TEST(Chi2Power, RejectsAPdfOnePercentOffInScale) {
  // CT at 82°: a fifth of its samples are rejected, so 0.99·pdf still integrates to less than 1 and only the
  // χ² statistic can catch it.
  const Brdf ct = CookTorrance{Rgb(0.0), Rgb(1.0), 0.3, 1.5};
  const Perturbed p{"CT pdf·0.99", ct, ct, 82 * kPi / 180.0};
  const Chi2Result r = perturbedChi2(p, 0.99);
  EXPECT_LT(r.pdfIntegral, 1.0);
  EXPECT_FALSE(r.passed) << r.message;
  EXPECT_FALSE(perturbedChi2(p, 1.01).passed);
}

// glossy sample's output, binned the same way, against the C++ pdf: the command writes what the sampler draws.
TEST(Chi2Cli, GlossySampleOutputFollowsThePdf) {
  struct Cli {
    std::string material, fit;
    double thetaV;
  };
  for (const Cli& c : {Cli{"chrome", "ashikhmin-shirley:E1", 0.6}, Cli{"blue-acrylic", "smooth:E2", 1.2}}) {
    const MaterialFile m = loadMaterialFile(materialsDir() / (c.material + ".toml"));
    const Brdf brdf = makeBrdf(*m.find(FitId::parse(c.fit, "test")));
    const Vec3 V = viewDirection(c.thetaV);
    std::ostringstream wo;
    wo.precision(17);
    wo << V.x << "," << V.y << "," << V.z;
    const long n = 200000;
    const RunResult r = runGlossy({"sample", "--material", (materialsDir() / (c.material + ".toml")).string(), "--fit",
                                   c.fit, "--wo", wo.str(), "-n", std::to_string(n), "--seed", "5"});
    ASSERT_EQ(r.status, 0) << r.err;
    std::istringstream lines(r.out);
    std::vector<std::optional<Vec3>> drawn;
    std::string line;
    while (std::getline(lines, line)) {
      double v[7];
      ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5],
                            &v[6]),
                7)
          << line;
      if (v[3] == 0.0)
        drawn.emplace_back(std::nullopt);
      else
        drawn.emplace_back(Vec3(v[0], v[1], v[2]));
    }
    ASSERT_EQ(long(drawn.size()), n);
    size_t next = 0;
    const DirectionSampler replay = [&](std::mt19937_64&) { return drawn[next++]; };
    const DirectionPdf density = [&](const Vec3& L) { return pdf(brdf, L, V); };
    const Chi2Result res = chi2Test(replay, density, gridFor(brdf, V), n, 0, 0.01 / 2);
    EXPECT_TRUE(res.passed) << c.material << " " << c.fit << ": " << res.message;
  }
}

}  // namespace glossy::test
