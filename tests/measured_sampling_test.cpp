// The measured sampler (materials/models/merl_sampling.h) draws from exactly its pdf: χ² on MERL-format
// tables written here (one tabulated from a very glossy Cook-Torrance lobe, one broad, one with unmeasured
// bins) and on shared/merl's six tables, in the same family as the analytic samplers
// (tests/sampling_chi2_test.cpp); negative controls; and a table tabulated from an analytic fit renders
// like the fit, within the table's own binning error.
#include "materials/merl/merl_table.h"
#include "renderer/integrator/path_tracer.h"
#include "tests/support/render_fixtures.h"
#include "tests/support/sampling_cases.h"
#include "tests/support/test_support.h"

#include <cmath>
#include <map>
#include <memory>

namespace glossy::test {

namespace {

constexpr long kSamples = 1000000;


const Brdf kGlossy = CookTorrance{Rgb(0.02), Rgb(0.6, 0.5, 0.4), 0.01, 1.8};
const Brdf kBroad = AshikhminShirley{Rgb(0.3, 0.2, 0.1), Rgb(0.3), 30.0, 1.5};
const Brdf kDiffuse = Lambertian{Rgb(0.5, 0.6, 0.7)};

struct SyntheticTable {
  const char* name;
  std::function<std::shared_ptr<const MerlTable>()> make;
};

const std::map<std::string, SyntheticTable>& syntheticTables() {
  static const std::map<std::string, SyntheticTable> tables = {
      {"glossy_ct_m0_01", {"Cook-Torrance m = 0.01", [] { return tabulateMerl(kGlossy); }}},
      {"broad_as_n30", {"Ashikhmin-Shirley n = 30 + diffuse", [] { return tabulateMerl(kBroad); }}},
      // Unmeasured bins as MERL has them (grazing θ_d) and a band in the middle.
      {"lambertian_with_holes",
       {"Lambertian with unmeasured bins", [] {
          return tabulateMerl(kDiffuse, [](int h, int d, int) { return d >= 85 || (h >= 30 && h < 36); });
        }}},
  };
  return tables;
}

// The sampler's own half-vector cells, each split in two in x and φ, so uniformity within a cell is tested.
HalfVectorGrid measuredGrid(const Vec3& V) {
  std::vector<double> edges;
  for (int i = 0; i <= MerlSampling::kThetaBins; ++i) {
    const double f = double(i) / MerlSampling::kThetaBins, s = std::sin(0.5 * f * f * kPi / 2);
    const double x = 2.0 * s * s;
    if (i > 0) edges.push_back(0.5 * (edges.back() + x));
    edges.push_back(x);
  }
  return HalfVectorGrid(V, edges, 2 * MerlSampling::kPhiBins);
}

struct MeasuredCase {
  std::string table;  // key of syntheticTables(), or "shared:NAME"
  double thetaV;
  std::string testName() const {
    std::string s = table + "_view" + std::to_string(int(std::lround(thetaV * 180.0 / kPi)));
    for (char& c : s)
      if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return s;
  }
};
void PrintTo(const MeasuredCase& c, std::ostream* os) { *os << c.testName(); }

std::vector<MeasuredCase> measuredFamily() {
  std::vector<MeasuredCase> all;
  for (const auto& [key, t] : syntheticTables())
    for (double theta : kViewAngles) all.push_back({key, theta});
  for (const std::string& name : supplementMaterials())  // shared/merl holds their tables
    for (double theta : kViewAngles) all.push_back({std::string("shared:") + name, theta});
  return all;
}

class MeasuredChi2 : public ::testing::TestWithParam<MeasuredCase> {};

}  // namespace

TEST(MeasuredChi2Family, IsAsLargeAsTheFamilySizeSaysAndTheGridSubdividesTheSamplersCells) {
  EXPECT_EQ(int(measuredFamily().size()), kMeasuredChi2Tests);
  const HalfVectorGrid grid = measuredGrid(viewDirection(0.3));
  EXPECT_EQ(grid.cellCount(), 2 * MerlSampling::kThetaBins * 2 * MerlSampling::kPhiBins);
}

TEST_P(MeasuredChi2, SampleDrawsFromExactlyThePdf) {
  const MeasuredCase& c = GetParam();
  std::shared_ptr<const MerlTable> table;
  if (c.table.rfind("shared:", 0) == 0) {
    const std::string name = c.table.substr(7);
    GLOSSY_REQUIRE_SHARED("merl/" + name + ".binary.xz");
    table = std::make_shared<const MerlTable>(MerlTable::load(sharedDir() / "merl" / (name + ".binary")));
  } else {
    table = syntheticTables().at(c.table).make();
  }
  const Brdf brdf = Measured(table);
  const Vec3 V = viewDirection(c.thetaV);
  uint32_t seed = 2166136261u;
  for (unsigned char ch : c.testName()) seed = (seed ^ ch) * 16777619u;
  const SamplingCheck check = checkSampler(brdf, V, measuredGrid(V), kSamples, seed, chi2TestAlpha());
  RecordProperty("pValue", std::to_string(check.chi2.pValue));
  EXPECT_TRUE(check.chi2.passed) << c.testName() << ": " << check.chi2.message;
  EXPECT_EQ(check.weightMismatches, 0) << c.testName();
  const double p = check.chi2.pdfIntegral;
  EXPECT_LE(p, 1.0 + 1e-7);
  EXPECT_NEAR(check.chi2.acceptance, p, 5.0 * std::sqrt(std::max(p * (1 - p), 1.0 / kSamples) / kSamples) + 1e-7)
      << check.chi2.message;
}

INSTANTIATE_TEST_SUITE_P(Tables, MeasuredChi2, ::testing::ValuesIn(measuredFamily()),
                         [](const auto& info) { return info.param.testName(); });

TEST(MeasuredChi2Power, RejectsATableSamplerBuiltFromSlightlyOtherDataOrMixedOtherwise) {
  const auto table = syntheticTables().at("glossy_ct_m0_01").make();
  const Measured claimed(table);
  const Vec3 V = viewDirection(35.0 * kPi / 180.0);
  // Tables built from a lobe 5 % wider than the data.
  Measured wider = claimed;
  wider.sampling = std::make_shared<const MerlSampling>(*tabulateMerl(CookTorrance{Rgb(0.02), Rgb(0.6, 0.5, 0.4), 0.0105, 1.8}));
  // The cosine share 0.13 instead of 0.1.
  Measured remixed = claimed;
  remixed.cosineWeight = 0.13;
  for (const Measured& drawn : {wider, remixed}) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const DirectionSampler draw = [&](std::mt19937_64& rng) -> std::optional<Vec3> {
      const double a = u(rng), b = u(rng), c = u(rng);
      const BrdfSample s = drawn.sample(V, a, Vec2(b, c));
      return s.valid() ? std::optional<Vec3>(s.L) : std::nullopt;
    };
    const Chi2Result r = chi2Test(draw, [&](const Vec3& L) { return claimed.pdf(L, V); }, measuredGrid(V), kSamples, 3,
                                  chi2TestAlpha());
    EXPECT_FALSE(r.passed) << r.message;
  }
}

TEST(MeasuredSampling, TablesAreSmallAndPdfIsContinuousAcrossViewElevations) {
  const auto table = syntheticTables().at("broad_as_n30").make();
  const MerlSampling sampling(*table);
  EXPECT_LT(sampling.bytes(), 64u << 20);
  // The densities of neighbouring view elevations are blended: a tiny change of V changes the pdf a little.
  const Vec3 L = Vec3(-0.4, 0.1, std::sqrt(1 - 0.17));
  for (double theta = 0.05; theta < 1.5; theta += 0.0491) {
    const double a = sampling.pdf(L, viewDirection(theta)), b = sampling.pdf(L, viewDirection(theta + 1e-6));
    EXPECT_NEAR(a, b, 1e-3 * a + 1e-12) << "θv " << theta;
  }
}


TEST(MeasuredRender, ATableOfAnAnalyticFitRendersLikeTheFitWithinItsBinningError) {
  const Brdf fit = CookTorrance{Rgb(0.1, 0.08, 0.05), Rgb(0.8, 0.6, 0.4), 0.12, 1.6};
  const Brdf table = Measured(tabulateMerl(fit));
  SceneDescription description;
  SceneMaterial object;
  object.name = "object";
  description.materials.push_back(object);
  description.meshes.push_back(uvSphere(1.0, 256, 128, 0));
  const EmbreeScene bvh(description);
  const Environment environment = Environment::constant(Rgb(1.0));
  RenderSettings settings;
  settings.width = settings.height = 1;
  settings.spp = 1 << 18;
  settings.progress = false;
  settings.maxDepth = 2;  // one reflection off a convex object under radiance 1: the directional albedo
  const auto renderPixel = [&](const Brdf& brdf, double thetaDeg) {
    const std::vector<Brdf> brdfs = {brdf};
    const RenderScene scene{&description, &bvh, brdfs, brdf, &environment};
    const double r = std::sin(thetaDeg * kPi / 180.0);
    const Camera c = orthographicDown(1e-3, {r, 0, 5}, {r, 0, 0}, {0, 1, 0});
    RenderStats stats;
    const RgbImage img = render(scene, c, settings, stats);
    return Rgb(img.at(0, 0)[0], img.at(0, 0)[1], img.at(0, 0)[2]);
  };
  for (double thetaDeg : {0.0, 30.0, 50.0, 65.0}) {
    const Vec3 V(std::sin(thetaDeg * kPi / 180.0), 0.0, std::cos(thetaDeg * kPi / 180.0));
    // A finer rule than for smooth lobes: the table is piecewise constant.
    const Rgb aTable = directionalAlbedo(table, V, 800, 1600), aFit = directionalAlbedo(fit, V, 800, 1600);
    const Rgb gotTable = renderPixel(table, thetaDeg), gotFit = renderPixel(fit, thetaDeg);
    for (int c = 0; c < 3; ++c) {
      const double binning = std::abs(aTable[c] - aFit[c]);
      RecordProperty("binningError" + std::to_string(int(thetaDeg)) + "RGB"[c], std::to_string(binning / aFit[c]));
      // The measured render is unbiased: it shows the table's own albedo (1 % ≈ 6σ at 2^18 spp) …
      EXPECT_NEAR(gotTable[c], aTable[c], 0.01 * aTable[c] + 1e-4) << "θv " << thetaDeg << "° channel " << c;
      // … which differs from the fit's render by no more than the binning error (+ both renders' noise).
      EXPECT_NEAR(gotTable[c], gotFit[c], binning + 0.01 * aFit[c] + 1e-4) << "θv " << thetaDeg << "° channel " << c;
    }
  }
}

}  // namespace glossy::test
