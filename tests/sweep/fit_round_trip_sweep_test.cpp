// A wider family of fitting round trips than the default suite's (tests/fitting_test.cpp): every model at
// a broad, a glossy and an extreme lobe, dielectric and metal-like η, under both metrics. Each table is
// tabulated at the bins' centres from the true parameters; the fit must reach the true parameters' E, with
// Kd and the lobe width within 5 % (but for the one exception below). CTest label `sweep` (about 6 min on
// 2 cores).
#include "materials/fitting/fitter.h"
#include "tests/support/test_support.h"

#include <cmath>
#include <cstdio>

namespace glossy::test {

namespace {

struct Case {
  std::string name;
  Fit truth;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  const Rgb kd(0.12, 0.07, 0.03);
  for (const char* metric : {"E1", "E2"}) {
    for (double eta : {1.45, 12.0}) {
      const std::string tag = std::string(metric) + (eta > 2 ? "_metal" : "_dielectric");
      for (double m : {0.4, 0.05, 0.006})
        out.push_back({"ct_m" + std::to_string(m).substr(0, 5) + "_" + tag,
                       makeFit("cook-torrance", metric, {{"kd", kd}, {"ks", Rgb(0.3, 0.25, 0.2)}, {"m", m}, {"eta", eta}})});
      for (double n : {8.0, 800.0, 40000.0})
        out.push_back({"as_n" + std::to_string(int(n)) + "_" + tag,
                       makeFit("ashikhmin-shirley", metric, {{"kd", kd}, {"ks", Rgb(0.5, 0.4, 0.3)}, {"n", n}, {"eta", eta}})});
      for (auto [b, c] : {std::pair{50.0, 1.8}, std::pair{5e3, 0.9}, std::pair{3e5, 0.6}}) {
        const Rgb a = Rgb(0.4, 0.3, 0.25) * std::sqrt(b) * 0.05;
        out.push_back({"microfacet_b" + std::to_string(int(b)) + "_" + tag,
                       makeFit("microfacet", metric, {{"kd", kd}, {"a", a}, {"b", b}, {"c", c}, {"eta", eta}})});
        out.push_back({"smooth_b" + std::to_string(int(b)) + "_" + tag,
                       makeFit("smooth", metric, {{"kd", kd}, {"a", a}, {"b", b}, {"c", c}, {"eta", eta}})});
      }
    }
  }
  for (auto& c : out)
    for (char& ch : c.name)
      if (ch == '.') ch = 'p';
  return out;
}

}  // namespace

class FitRoundTripSweep : public ::testing::TestWithParam<Case> {};

TEST_P(FitRoundTripSweep, ReachesTheTrueErrorWithKdAndTheLobeWidthWithinFivePerCent) {
  const Fit& truth = GetParam().truth;
  const auto table = tabulateMerl(makeBrdf(truth));
  const MetricData data(*table, truth.id.metric == "E1" ? Metric::E1 : Metric::E2);
  const double trueError = data.error(makeBrdf(truth));
  const FitReport report = fitModel(data, truth.id.model);
  EXPECT_LE(report.error, trueError * (1.0 + 1e-9));
  const Rgb kd = report.fit.params.rgb("kd"), kdTrue = truth.params.rgb("kd");
  // A bright (F(0) > 0.5) lobe narrower than 0.01 under E1 is the documented exception (docs/fitting.md):
  // its absolute values at the peak are hundreds of times Kd/π, MERL's bins misstate them by tens of per
  // cent there, and the E1 minimum of the binned data is not at the true parameters.
  const bool binningDominates = truth.id.metric == "E1" && lobeWidth(truth) < 0.01 &&
                                fresnelCookTorrance(1.0, truth.params.scalar("eta")) > 0.5;
  if (!binningDominates) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(kd[c], kdTrue[c], 0.05 * kdTrue[c]) << "Kd channel " << c;
    EXPECT_NEAR(lobeWidth(report.fit), lobeWidth(truth), 0.05 * lobeWidth(truth));
  }
  std::printf("[ report   ] %s: E %.5g / true %.5g, Kd [%.4g %.4g %.4g], width %.4g / true %.4g, %.1f s%s\n", GetParam().name.c_str(),
              report.error, trueError, kd.r, kd.g, kd.b, lobeWidth(report.fit), lobeWidth(truth), report.seconds,
              binningDominates ? " (binning-dominated: Kd and width reported, not asserted)" : "");
}

INSTANTIATE_TEST_SUITE_P(Family, FitRoundTripSweep, ::testing::ValuesIn(cases()),
                         [](const auto& info) { return info.param.name; });

}  // namespace glossy::test
