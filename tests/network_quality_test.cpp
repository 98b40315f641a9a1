// The Neural BRDF data-quality figures (bench/network_quality.h) of a network whose values are known in
// closed form, against those values computed here bin by bin without the network.
#include "bench/network_quality.h"
#include "materials/core/text.h"
#include "tests/support/test_support.h"

#include <cmath>

namespace glossy::test {

// One linear layer: R = expm1(sin θ_d cos φ_d − 0.125), negative where |sin θ_d cos φ_d| is small and not
// reciprocal; G = expm1(−0.5) < 0 everywhere; B = expm1(ln 3) = 2 everywhere, a Lambertian of albedo 2π.
TEST(NetworkQuality, FiguresOfAClosedFormNetwork) {
  const float lnThree = std::log(3.0f);
  const std::string text = "format = \"glossy-nbrdf 1\"\nmaterial = \"closed-form\"\nlabel = \"test\"\n"
                           "input = \"half-difference\"\noutput = \"expm1\"\n[[layer]]\ninputs = 6\noutputs = 3\n"
                           "activation = \"linear\"\n"
                           "weights = [0, 0, 0, 1, 0, 0,  0, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 0]\n"
                           "biases = [-0.125, -0.5, " + formatted("%.9g", double(lnThree)) + "]\n";
  const NeuralBrdf network = NeuralBrdf::parse(text, "closed-form.nbrdf");
  const MerlTable table = network.tabulate();
  const bench::NetworkQuality q = bench::assessNetwork(network, table);

  size_t measured = 0, negativeR = 0;
  double lowestR = 0.0, squaredDifference = 0.0, squaredMean = 0.0, asymmetryMax = 0.0;
  const double blue = std::expm1(double(lnThree)), green = std::expm1(-0.5);
  for (int i = 0; i < MerlTable::kThetaH; ++i)
    for (int j = 0; j < MerlTable::kThetaD; ++j)
      for (int k = 0; k < MerlTable::kPhiD; ++k) {
        if (!table.valid(MerlBin{i, j, k}.index())) continue;
        ++measured;
        const double s = std::sin(j * kPi / 180.0);
        const double a = std::expm1(s * std::cos(k * kPi / 180.0) - 0.125);
        const double b = std::expm1(s * std::cos((k + 180) * kPi / 180.0) - 0.125);
        const double mean = 0.5 * (a + b);
        if (mean < 0.0) ++negativeR, lowestR = std::min(lowestR, mean);
        squaredDifference += (a - b) * (a - b);
        squaredMean += mean * mean + green * green + blue * blue;
        if (mean >= bench::NetworkQuality::kAsymmetryFloor) asymmetryMax = std::max(asymmetryMax, std::abs(a - b) / mean);
      }
  ASSERT_GT(negativeR, 0u);
  ASSERT_LT(negativeR, measured);
  EXPECT_EQ(q.measuredBins, measured);
  EXPECT_EQ(q.measuredBins, MerlTable::kBins - table.invalidBins());
  EXPECT_EQ(q.negativeBins[0], negativeR);
  EXPECT_EQ(q.negativeBins[1], measured);
  EXPECT_EQ(q.negativeBins[2], 0u);
  EXPECT_DOUBLE_EQ(q.negativeShare(1), 1.0);
  EXPECT_NEAR(q.lowest[0], lowestR, 1e-15);
  EXPECT_NEAR(q.lowest[1], green, 1e-15);
  EXPECT_EQ(q.lowest[2], 0.0);
  EXPECT_EQ(q.nonFiniteBins, 0u);
  EXPECT_NEAR(q.asymmetryRms, std::sqrt(squaredDifference / squaredMean), 1e-12);
  EXPECT_GT(q.asymmetryRms, 0.01);
  EXPECT_NEAR(q.asymmetryMax, asymmetryMax, 1e-12);
  // The tabulated B is float(2 / scale) × scale: 2 to float precision, its albedo 2π at every θ_V the mask
  // leaves whole; R's stays below 1.6 π.
  EXPECT_EQ(q.maxAlbedoChannel, 2);
  EXPECT_NEAR(q.maxAlbedo, 2.0 * kPi, 1e-5);
}

}  // namespace glossy::test
