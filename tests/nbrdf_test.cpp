// Neural BRDFs (materials/nbrdf/neural_brdf.h): the file format and its bad input; the network's forward
// pass; the six embedded networks tabulated into exactly shared/merl's reconstructed tables; a sheet from a
// network against one from its table.
#include "materials/core/input_error.h"
#include "materials/core/lane_math.h"
#include "materials/nbrdf/neural_brdf.h"
#include "renderer/sheet/sheet.h"
#include "tests/support/test_support.h"

#include <bit>
#include <chrono>
#include <cmath>
#include <cstring>
#include <sstream>

namespace glossy::test {

namespace {

std::filesystem::path embedded(const std::string& name) { return materialsDir() / (name + ".nbrdf"); }

std::string numbers(const std::vector<double>& v) {
  std::ostringstream s;
  s.precision(17);
  s << "[";
  for (size_t i = 0; i < v.size(); ++i) s << (i ? ", " : "") << v[i];
  return s.str() + "]";
}

struct TestLayer {
  int inputs, outputs;
  std::string activation;
  std::vector<double> weights, biases;
};

std::string networkText(const std::vector<TestLayer>& layers, const std::string& head = "") {
  std::string text = head.empty() ? "format = \"glossy-nbrdf 1\"\nmaterial = \"test\"\nlabel = \"Test (NBRDF reconstruction)\"\n"
                                    "input = \"half-difference\"\noutput = \"expm1\"\n"
                                  : head;
  for (const TestLayer& l : layers)
    text += "[[layer]]\ninputs = " + std::to_string(l.inputs) + "\noutputs = " + std::to_string(l.outputs) +
            "\nactivation = \"" + l.activation + "\"\nweights = " + numbers(l.weights) + "\nbiases = " + numbers(l.biases) + "\n";
  return text;
}

// 6 → 2 (ReLU) → 3: small enough to evaluate by hand; its weights are floats, as every network's are.
std::vector<TestLayer> smallNetwork() {
  return {{6, 2, "relu", {0.5, 0, 0.25, 1, -1, 0.125, -0.5, 0, 0, 0, 0, 1}, {0.125, -0.25}},
          {2, 3, "linear", {1, 0, 0, 1, 0.5, 0.5}, {0, 0.0625, -0.0625}}};
}

}  // namespace

TEST(NeuralBrdf, ForwardPassIsTheDocumentedNetwork) {
  const NeuralBrdf n = NeuralBrdf::parse(networkText(smallNetwork()), "small.nbrdf");
  const double th = 0.3, td = 0.7, pd = 0.3;
  const double x[6] = {std::sin(th), 0.0, std::cos(th), std::sin(td) * std::cos(pd), std::sin(td) * std::sin(pd), std::cos(td)};
  const double h0 = std::max(0.0, 0.5 * x[0] + 0.25 * x[2] + x[3] - x[4] + 0.125 * x[5] + 0.125);
  const double h1 = std::max(0.0, -0.5 * x[0] + x[5] - 0.25);
  const Rgb rho = n.evalAngles(th, td, pd);
  EXPECT_NEAR(rho.r, std::expm1(h0), 1e-15);
  EXPECT_GT(h0, 0.0);
  EXPECT_GT(h1, 0.0);
  EXPECT_NEAR(rho.g, std::expm1(h1 + 0.0625), 1e-15);
  EXPECT_NEAR(rho.b, std::expm1(0.5 * h0 + 0.5 * h1 - 0.0625), 1e-15);
}

TEST(NeuralBrdf, BadFilesAreInputErrorsNamingTheFile) {
  const auto error = [](const std::string& text) {
    return expectInputError([&] { NeuralBrdf::parse(text, "bad.nbrdf"); });
  };
  std::vector<TestLayer> layers = smallNetwork();
  EXPECT_NE(error("format = \"glossy-nbrdf 1\"\nmaterial = [").find("bad.nbrdf:2"), std::string::npos);
  EXPECT_NE(error(networkText(layers, "format = \"glossy-nbrdf 2\"\nmaterial = \"x\"\ninput = \"half-difference\"\noutput = \"expm1\"\n"))
                .find("glossy-nbrdf 2"),
            std::string::npos);
  EXPECT_NE(error(networkText(layers, "format = \"glossy-nbrdf 1\"\nmaterial = \"x\"\ninput = \"cartesian\"\noutput = \"expm1\"\n"))
                .find("cartesian"),
            std::string::npos);
  EXPECT_NE(error(networkText({})).find("[[layer]]"), std::string::npos);
  // Every result names the database by the network's label: a network without one is refused.
  EXPECT_NE(error(networkText(layers, "format = \"glossy-nbrdf 1\"\nmaterial = \"x\"\ninput = \"half-difference\"\noutput = \"expm1\"\n"))
                .find("label"),
            std::string::npos);

  std::vector<TestLayer> chain = layers;
  chain[1].inputs = 3;
  chain[1].weights.resize(9);
  EXPECT_NE(error(networkText(chain)).find("3 inputs, but 2"), std::string::npos);
  std::vector<TestLayer> shortWeights = layers;
  shortWeights[0].weights.pop_back();
  EXPECT_NE(error(networkText(shortWeights)).find("bad.nbrdf:10: layer 1: key 'weights' has 11 numbers, expected 12"), std::string::npos)
      << error(networkText(shortWeights));
  std::vector<TestLayer> nan = layers;
  std::string text = networkText(nan);
  const std::string biases = "biases = [0.125, -0.25]";
  ASSERT_NE(text.find(biases), std::string::npos) << text;
  text.replace(text.find(biases), biases.size(), "biases = [nan, -0.25]");
  EXPECT_NE(error(text).find("non-finite"), std::string::npos);
  std::vector<TestLayer> relu = layers;
  relu[1].activation = "relu";
  EXPECT_NE(error(networkText(relu)).find("linear"), std::string::npos);
  std::vector<TestLayer> tanh = layers;
  tanh[0].activation = "tanh";
  EXPECT_NE(error(networkText(tanh)).find("tanh"), std::string::npos);
  std::vector<TestLayer> wide = layers;
  wide[0].outputs = 100000;
  EXPECT_NE(error(networkText(wide)).find("from 1 to 225"), std::string::npos);
  std::vector<TestLayer> four = layers;
  four[1] = {2, 4, "linear", std::vector<double>(8, 0.0), std::vector<double>(4, 0.0)};
  EXPECT_NE(error(networkText(four)).find("4 outputs, expected 3"), std::string::npos);

  TempDir tmp;
  EXPECT_NE(expectInputError([&] { NeuralBrdf::load(tmp / "absent.nbrdf"); }).find("absent.nbrdf"), std::string::npos);
  EXPECT_NE(expectInputError([&] { NeuralBrdf::load(tmp.path()); }).find("is a folder"), std::string::npos);
  writeText(tmp / "huge.nbrdf", std::string(NeuralBrdf::kMaxBytes + 1, '#'));
  EXPECT_NE(expectInputError([&] { NeuralBrdf::load(tmp / "huge.nbrdf"); }).find("too large"), std::string::npos);
}

namespace {

// A network of these widths (6 first, 3 last), ReLU between, its weights all zero.
std::vector<TestLayer> zeroNetwork(const std::vector<int>& widths) {
  std::vector<TestLayer> layers;
  for (size_t k = 0; k + 1 < widths.size(); ++k)
    layers.push_back({widths[k], widths[k + 1], k + 2 == widths.size() ? "linear" : "relu",
                      std::vector<double>(size_t(widths[k]) * size_t(widths[k + 1]), 0.0), std::vector<double>(size_t(widths[k + 1]), 0.0)});
  return layers;
}

}  // namespace

// Every load tabulates the network 2.9 million times, so its cost grows with its size: a larger network than
// the supplement's is refused from its layers' sizes, before its weights are read, so that a file cut short in its weights still gets the size error.
TEST(NeuralBrdf, NetworksLargerThanTheSupplementsAreRefusedBeforeTheirWeights) {
  EXPECT_NO_THROW(NeuralBrdf::parse(networkText(zeroNetwork({6, 21, 21, 3})), "supplement.nbrdf"));
  for (const std::vector<int>& widths : std::vector<std::vector<int>>{{6, 22, 21, 3}, {6, 21, 21, 21, 3}, {6, 64, 64, 3}}) {
    std::vector<TestLayer> layers = zeroNetwork(widths);
    layers.back().weights.clear();  // never read: the architecture alone is refused
    const std::string e = expectInputError([&] { NeuralBrdf::parse(networkText(layers), "big.nbrdf"); });
    EXPECT_NE(e.find("big.nbrdf: more than 675 weights and biases"), std::string::npos) << e;
  }
  // The 11 MB network of the report: 6 -> 1024 -> 1024 -> 3 as a file, refused by its size unread.
  TempDir tmp;
  const std::string big = networkText(zeroNetwork({6, 1024, 1024, 3}));
  ASSERT_GT(big.size(), NeuralBrdf::kMaxBytes);
  writeText(tmp / "big.nbrdf", big);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_NE(expectInputError([&] { NeuralBrdf::load(tmp / "big.nbrdf"); }).find("too large"), std::string::npos);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

// The geometric stand-in for the unmeasured bins (SOURCES.md) is shared/merl's mask, bin for bin.
TEST(NeuralBrdf, UnmeasuredBinsAreSharedMerlsMask) {
  GLOSSY_REQUIRE_SHARED("merl/gold-paint.binary.xz");
  const MerlTable table = MerlTable::load(sharedDir() / "merl/gold-paint.binary");
  const MerlTable tabulated = NeuralBrdf::parse(networkText(smallNetwork()), "small.nbrdf").tabulate();
  EXPECT_EQ(tabulated.invalidBins(), table.invalidBins());
  size_t differ = 0;
  for (size_t i = 0; i < MerlTable::kBins; ++i) differ += tabulated.valid(i) != table.valid(i);
  EXPECT_EQ(differ, 0u);
}

// The six embedded networks, tabulated by SOURCES.md's procedure, are shared/merl's tables: every bin's
// validity, and every valid value to one float (the reconstructions summed in another order, so a value
// that lies within rounding of a float boundary may land on the float beside it).
TEST(NeuralBrdf, EmbeddedNetworksTabulateToSharedMerlsTables) {
  GLOSSY_REQUIRE_SHARED("merl/gold-paint.binary.xz");
  // The stored (unscaled) float of a value; value() multiplied it by the scale in double, which dividing
  // undoes to far better than float rounding.
  const auto stored = [](double value, int c) { return std::bit_cast<int32_t>(float(value / MerlTable::kScale[c])); };
  for (const std::string& name : supplementMaterials()) {
    const MerlTable table = MerlTable::load(sharedDir() / "merl" / (std::string(name) + ".binary"));
    const MerlTable tabulated = NeuralBrdf::load(embedded(name)).tabulate();
    size_t valid = 0, unequal = 0, apart = 0;
    for (size_t i = 0; i < MerlTable::kBins; ++i) {
      ASSERT_EQ(tabulated.valid(i), table.valid(i)) << name << " bin " << i;
      if (!table.valid(i)) continue;
      ++valid;
      const Rgb a = tabulated.value(i), b = table.value(i);
      for (int c = 0; c < 3; ++c) {
        // Both are non-negative floats, whose bit patterns count floats: their distance in floats.
        const int64_t floats = std::abs(int64_t(stored(a[c], c)) - int64_t(stored(b[c], c)));
        unequal += floats > 0;
        apart += floats > 1;
      }
    }
    RecordProperty(std::string(name) + "_unequal", std::to_string(unequal));
    EXPECT_EQ(valid, MerlTable::kBins - table.invalidBins()) << name;
    EXPECT_EQ(apart, 0u) << name << ": values more than one float apart";
    EXPECT_LE(unequal, 10u) << name << ": values one float apart (the summation order's rounding, expected rare)";
  }
}

// tabulate() evaluates many bins side by side, on AVX2 where the CPU has it: every value is the one
// evalAngles gives for its bin, on either path.
TEST(NeuralBrdf, TabulatedValuesAreEvalAnglesOnEveryPath) {
  const NeuralBrdf n = NeuralBrdf::load(embedded("chrome"));
  const auto expected = [&](int i, int j, int k) {
    const double degree = kPi / 180.0, thetaH = double(i) * i / (90 * 90) * (kPi / 2.0);
    const Rgb a = n.evalAngles(thetaH, j * degree, k * degree), b = n.evalAngles(thetaH, j * degree, (k + 180) * degree);
    Rgb v;
    for (int c = 0; c < 3; ++c) v[c] = double(float(std::max(0.5 * (a[c] + b[c]), 0.0) / MerlTable::kScale[c])) * MerlTable::kScale[c];
    return v;
  };
  const lanes::Isa original = lanes::isa();
  std::vector<MerlTable> tables;
  for (lanes::Isa isa : {lanes::Isa::Sse2, lanes::Isa::Avx2}) {
    if (!lanes::setIsa(isa)) continue;
    tables.push_back(n.tabulate());
  }
  lanes::setIsa(original);
  for (const MerlTable& t : tables) {
    size_t checked = 0;
    // Every bin of a few rows (each of a batch's lanes, the row ends), and a stride through the rest.
    for (size_t bin = 0; bin < MerlTable::kBins; bin += (bin < 40000 || bin > MerlTable::kBins - 40000) ? 1 : 7919) {
      if (!t.valid(bin)) continue;
      const int i = int(bin / (180 * 90)), j = int(bin / 180 % 90), k = int(bin % 180);
      ASSERT_EQ(t.value(bin), expected(i, j, k)) << "bin " << bin;
      ++checked;
    }
    EXPECT_GT(checked, 40000u);
  }
  if (tables.size() == 2) {
    size_t differ = 0;
    for (size_t bin = 0; bin < MerlTable::kBins; ++bin) differ += tables[0].value(bin) != tables[1].value(bin);
    EXPECT_EQ(differ, 0u);
  }
}

// A sheet whose measured panel comes from the network is the sheet from its table, bit for bit.
TEST(NeuralBrdf, SheetFromTheNetworkIsTheSheetFromTheTable) {
  GLOSSY_REQUIRE_SHARED("merl/gold-paint.binary.xz");
  const SceneDescription description = loadGltf(sourceDir() / "scenes/preview.gltf");
  const EmbreeScene bvh(description);
  const Environment environment = Environment::makeDefault();
  const SheetScene scene = makeSheetScene(description, bvh, environment, description.cameras.front());
  const MaterialFile m = loadMaterialFile(materialsDir() / "gold-paint.toml");
  SheetSettings settings;
  settings.width = settings.height = 48;
  settings.spp = 16;
  settings.threads = 2;
  settings.progress = false;
  const Sheet fromTable = renderSheet(scene, m, std::make_shared<const MerlTable>(MerlTable::load(sharedDir() / "merl/gold-paint.binary")),
                                      "table", settings);
  const Sheet fromNetwork = renderSheet(scene, m, std::make_shared<const MerlTable>(NeuralBrdf::load(embedded("gold-paint")).tabulate()),
                                        "network", settings);
  ASSERT_EQ(fromTable.panels.size(), fromNetwork.panels.size());
  EXPECT_FALSE(fromNetwork.measured()->empty);
  for (size_t k = 0; k < fromTable.panels.size(); ++k)
    EXPECT_EQ(fromTable.panels[k].image.pixels, fromNetwork.panels[k].image.pixels) << "panel " << k;
  for (size_t k = 0; k < fromTable.panels.size(); ++k) {
    EXPECT_EQ(fromTable.panels[k].figures.relativeRmse, fromNetwork.panels[k].figures.relativeRmse) << "panel " << k;
    EXPECT_EQ(fromTable.panels[k].brdfE2, fromNetwork.panels[k].brdfE2) << "panel " << k;
  }
  EXPECT_TRUE(fromNetwork.panels.back().figures.compared);
}

}  // namespace glossy::test
