// The MERL reader and reference lookup on synthetic 90×90×180 tables written here (format, lookup, bin
// edges, reciprocity fold, invalid bins, bad files), and on shared/merl/blue-rubber when present.
#include "materials/core/input_error.h"
#include "materials/merl/merl_table.h"
#include "tests/support/test_support.h"

#include <lzma.h>

#include <cmath>
#include <cstring>
#include <glm/common.hpp>
#include <random>

namespace glossy::test {

namespace {

constexpr double kHalfPi = kPi / 2;

// Stored value = the bin's own coordinates, so a lookup says which bin it chose.
Rgb coordinates(int h, int d, int p) { return {double(h), double(d), double(p)}; }

std::span<const std::byte> asBytes(const std::string& s) { return {reinterpret_cast<const std::byte*>(s.data()), s.size()}; }

const MerlTable& coordinateTable() {
  static const MerlTable table = MerlTable::parse(asBytes(syntheticMerlBytes(coordinates)), "synthetic");
  return table;
}

MerlBin lookedUp(const Vec3& L, const Vec3& V) {
  const Rgb v = coordinateTable().eval(L, V);
  return {int(std::lround(v.r / MerlTable::kScale[0])), int(std::lround(v.g / MerlTable::kScale[1])),
          int(std::lround(v.b / MerlTable::kScale[2]))};
}

double thetaHEdge(int i) { return double(i) * i / (90.0 * 90.0) * kHalfPi; }  // lower edge of bin i

std::string xzCompress(const std::string& data) {
  std::string out(lzma_stream_buffer_bound(data.size()), '\0');
  size_t pos = 0;
  const lzma_ret r = lzma_easy_buffer_encode(0, LZMA_CHECK_CRC64, nullptr, reinterpret_cast<const uint8_t*>(data.data()),
                                             data.size(), reinterpret_cast<uint8_t*>(out.data()), &pos, out.size());
  if (r != LZMA_OK) throw std::runtime_error("xz encode failed");
  out.resize(pos);
  return out;
}

}  // namespace

TEST(Merl, ScalesChannelsAsTheReferenceReader) {
  const MerlTable t = MerlTable::parse(asBytes(syntheticMerlBytes([](int, int, int) { return Rgb(1500.0); })), "ones");
  const auto [L, V] = fromHalfDiff(0.3, 0.4, 1.0);
  const Rgb v = t.eval(L, V);
  EXPECT_DOUBLE_EQ(v.r, 1.0);
  EXPECT_DOUBLE_EQ(v.g, 1.15);
  EXPECT_DOUBLE_EQ(v.b, 1.66);
  EXPECT_EQ(t.invalidBins(), 0u);
}

TEST(Merl, BinCentresLookUpTheirOwnBinForAnyAzimuthOfTheHalfVector) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 2 * kPi);
  int checked = 0;
  for (int h = 0; h < 90; h += 7)
    for (int d = 0; d < 90; d += 11)
      for (int p = 0; p < 180; p += 13) {
        const double th = std::pow((h + 0.5) / 90.0, 2) * kHalfPi, td = (d + 0.5) / 90.0 * kHalfPi, pd = (p + 0.5) / 180.0 * kPi;
        const auto [L, V] = fromHalfDiff(th, td, pd, u(rng));
        if (L.z <= 1e-6 || V.z <= 1e-6) continue;
        const MerlBin b = lookedUp(L, V);
        EXPECT_EQ(b.thetaH, h);
        EXPECT_EQ(b.thetaD, d);
        EXPECT_EQ(b.phiD, p);
        ++checked;
      }
  EXPECT_GT(checked, 300);
}

TEST(Merl, ThetaHalfBinsAreSquareRootSpacedWithNearestLowerEdges) {
  for (int i = 1; i < 90; ++i) {
    const double edge = thetaHEdge(i);
    if (edge + 0.2 >= kHalfPi) break;
    const auto above = fromHalfDiff(edge * (1 + 1e-7), 0.2, 1.0), below = fromHalfDiff(edge * (1 - 1e-7), 0.2, 1.0);
    EXPECT_EQ(lookedUp(above.first, above.second).thetaH, i);
    EXPECT_EQ(lookedUp(below.first, below.second).thetaH, i - 1);
  }
  const auto [L, V] = fromHalfDiff(0.0, 0.3, 0.5);  // θ_h = 0 exactly
  EXPECT_EQ(lookedUp(L, V).thetaH, 0);
}

TEST(Merl, ThetaDiffAndPhiDiffBinsAreUniform) {
  for (int j = 1; j < 80; ++j) {
    const double edge = j / 90.0 * kHalfPi;
    const auto a = fromHalfDiff(0.01, edge + 1e-9, 0.5), b = fromHalfDiff(0.01, edge - 1e-9, 0.5);
    EXPECT_EQ(lookedUp(a.first, a.second).thetaD, j);
    EXPECT_EQ(lookedUp(b.first, b.second).thetaD, j - 1);
  }
  for (int k = 1; k < 180; ++k) {
    const double edge = k / 180.0 * kPi;
    const auto a = fromHalfDiff(0.01, 0.3, edge + 1e-9), b = fromHalfDiff(0.01, 0.3, edge - 1e-9);
    EXPECT_EQ(lookedUp(a.first, a.second).phiD, k);
    EXPECT_EQ(lookedUp(b.first, b.second).phiD, k - 1);
  }
}

TEST(Merl, ReciprocityFoldMapsPhiAndPhiPlusPiToOneBin) {
  for (int k = 0; k < 180; k += 5) {
    const double pd = (k + 0.5) / 180.0 * kPi;
    const auto a = fromHalfDiff(0.05, 0.4, pd), b = fromHalfDiff(0.05, 0.4, pd + kPi);
    EXPECT_EQ(lookedUp(b.first, b.second).phiD, k);
    EXPECT_EQ(lookedUp(a.first, a.second).index(), lookedUp(b.first, b.second).index());
    // Swapping L and V is exactly φ_d → φ_d + π.
    EXPECT_EQ(lookedUp(a.second, a.first).index(), lookedUp(a.first, a.second).index());
  }
}

TEST(Merl, BelowTheHorizonIsZero) {
  const auto [L, V] = fromHalfDiff(0.2, 0.5, 1.0);
  EXPECT_EQ(coordinateTable().eval(Vec3(L.x, L.y, -L.z), V), Rgb(0.0));
  EXPECT_EQ(coordinateTable().eval(L, Vec3(V.x, V.y, -V.z)), Rgb(0.0));
}

TEST(Merl, NegativeBinsAreInvalidInAllChannelsAndCounted) {
  // Mark bins with θ_d index 45 and φ_d index 7 invalid through one negative channel each.
  const MerlTable t = MerlTable::parse(asBytes(syntheticMerlBytes([](int h, int d, int p) {
                                          Rgb v(3.0, 4.0, 5.0);
                                          if (d == 45 && p == 7) v[h % 3] = -1.0;
                                          return v;
                                        })),
                                        "holes");
  EXPECT_EQ(t.invalidBins(), 90u);
  const double td = 45.5 / 90.0 * kHalfPi, pd = 7.5 / 180.0 * kPi;
  const auto [L, V] = fromHalfDiff(0.1, td, pd);
  EXPECT_EQ(t.eval(L, V), Rgb(0.0));
  EXPECT_FALSE(t.valid(MerlTable::binOf(L, V).index()));
  const auto ok = fromHalfDiff(0.1, td, pd + kPi / 180);
  EXPECT_GT(t.eval(ok.first, ok.second).r, 0.0);
}

TEST(Merl, BadFilesAreErrorsNamingTheFile) {
  const std::string good = syntheticMerlBytes([](int, int, int) { return Rgb(1.0); });
  TempDir tmp;
  auto loadBytes = [&](const std::string& name, const std::string& bytes) {
    writeText(tmp / name, bytes);
    return expectInputError([&] { MerlTable::load(tmp / name); });
  };
  std::string e = loadBytes("truncated.binary", good.substr(0, good.size() - 8));
  EXPECT_NE(e.find("truncated.binary"), std::string::npos) << e;
  EXPECT_NE(e.find("truncated"), std::string::npos) << e;
  e = loadBytes("short.binary", good.substr(0, 5));
  EXPECT_NE(e.find("short.binary: truncated"), std::string::npos) << e;
  e = loadBytes("long.binary", good + "12345678");
  EXPECT_NE(e.find("oversized"), std::string::npos) << e;
  std::string header = good;
  header[0] = 91;
  e = loadBytes("header.binary", header);
  EXPECT_NE(e.find("header.binary: not a MERL BRDF (header 91x90x180"), std::string::npos) << e;
  std::string nan = good;
  const double q = std::nan("");
  std::memcpy(nan.data() + 12 + 8 * 1000, &q, 8);
  e = loadBytes("nan.binary", nan);
  EXPECT_NE(e.find("nan.binary: non-finite value"), std::string::npos) << e;
  e = expectInputError([&] { MerlTable::load(tmp / "missing.binary"); });
  EXPECT_NE(e.find("missing.binary: cannot open"), std::string::npos) << e;
  e = expectInputError([&] { MerlTable::load(tmp.path()); });
  EXPECT_NE(e.find("is a folder"), std::string::npos) << e;
}

// Huge values are corrupt data, and beyond float's range they overflowed the sampler's sums into
// "Distribution2D: negative or non-finite value" (exit 1) in every command: now the table is bad input.
TEST(Merl, ValuesAboveThePlausibleMaximumAreErrorsNamingFileAndBin) {
  auto tableWith = [](double stored) {
    return syntheticMerlBytes([stored](int h, int d, int p) { return h == 3 && d == 5 && p == 7 ? Rgb(1.0, stored, 1.0) : Rgb(1.0); });
  };
  // Stored values are scaled by kScale (G: 1.15 / 1500) on reading.
  const double maxStoredG = MerlTable::kMaxValue / MerlTable::kScale[1];
  for (double stored : {1e300, 1e39, 3.5e38, maxStoredG * 1.0001}) {
    const std::string e = expectInputError([&] { MerlTable::parse(asBytes(tableWith(stored)), "huge.binary"); });
    EXPECT_NE(e.find("huge.binary: value"), std::string::npos) << e;
    EXPECT_NE(e.find("channel G at bin (θh 3, θd 5, φd 7)"), std::string::npos) << e;
    EXPECT_NE(e.find("plausible maximum"), std::string::npos) << e;
  }
  const MerlTable t = MerlTable::parse(asBytes(tableWith(maxStoredG * 0.9999)), "bright.binary");
  EXPECT_NEAR(t.value(MerlBin{3, 5, 7}.index()).g, MerlTable::kMaxValue * 0.9999, MerlTable::kMaxValue * 1e-6);  // stored as float
  EXPECT_EQ(t.invalidBins(), 0u);

  TempDir tmp;
  const std::string huge = (tmp / "huge.binary").string();
  writeText(huge, tableWith(1e300));
  const std::vector<std::string> small = {"--width", "8", "--height", "8", "--spp", "1"};
  std::vector<std::vector<std::string>> commands = {
      {"render", "--measured", huge, "-o", (tmp / "x.exr").string()},
      {"sample", "--measured", huge, "--wo", "0,0,1", "-n", "4"},
      {"error", "--material", (materialsDir() / "chrome.toml").string(), "--measured", huge},
      {"fit", "--measured", huge, "--model", "cook-torrance", "--metric", "E2"},
      {"sheet", "--material", (materialsDir() / "chrome.toml").string(), "--measured", huge, "-o", (tmp / "x.exr").string()}};
  for (auto& c : commands)
    if (c[0] == "render" || c[0] == "sheet") c.insert(c.end(), small.begin(), small.end());
  for (const auto& c : commands) {
    SCOPED_TRACE(c[0]);
    expectOneLineError(runGlossy(c), "huge.binary: value");
  }
  expectOneLineError(runGlossy({"eval", "--measured", huge}, "0.3,0,0.954,-0.3,0,0.954\n"), "huge.binary: value");
  EXPECT_FALSE(std::filesystem::exists(tmp / "x.exr"));
}

TEST(Merl, CompressedTablesReadLikePlainOnesAndStandInForAbsentOnes) {
  const std::string bytes = syntheticMerlBytes(coordinates);
  TempDir tmp;
  writeText(tmp / "plain.binary", bytes);
  const std::string xz = xzCompress(bytes);
  writeText(tmp / "packed.binary.xz", xz);
  const MerlTable plain = MerlTable::load(tmp / "plain.binary");
  const MerlTable packed = MerlTable::load(tmp / "packed.binary");  // absent: NAME.binary.xz stands in
  for (size_t i = 0; i < MerlTable::kBins; i += 997) EXPECT_EQ(plain.value(i), packed.value(i));
  writeText(tmp / "cut.binary.xz", xz.substr(0, xz.size() / 2));
  std::string e = expectInputError([&] { MerlTable::load(tmp / "cut.binary.xz"); });
  EXPECT_NE(e.find("cut.binary.xz: truncated xz data"), std::string::npos) << e;
  writeText(tmp / "junk.binary.xz", "not xz at all");
  e = expectInputError([&] { MerlTable::load(tmp / "junk.binary.xz"); });
  EXPECT_NE(e.find("junk.binary.xz: not an xz file"), std::string::npos) << e;
}

TEST(Merl, SharedBlueRubberReconstruction) {
  GLOSSY_REQUIRE_SHARED("merl/blue-rubber.binary.xz");
  const MerlTable t = MerlTable::load(sharedDir() / "merl/blue-rubber.binary.xz");
  // SOURCES.md: the geometric stand-in mask marks 351,322 bins invalid in every reconstruction.
  EXPECT_EQ(t.invalidBins(), 351322u);
  // Decompressed by the xz tool to a plain .binary, it reads identically.
  TempDir tmp;
  const std::string cmd = "xz -dc '" + (sharedDir() / "merl/blue-rubber.binary.xz").string() + "' > '" +
                          (tmp / "blue-rubber.binary").string() + "'";
  if (std::system(cmd.c_str()) != 0) GTEST_SKIP() << "the xz tool is not installed (scripts/setup installs it)";
  const MerlTable plain = MerlTable::load(tmp / "blue-rubber.binary");
  for (size_t i = 0; i < MerlTable::kBins; i += 101) ASSERT_EQ(plain.value(i), t.value(i));
  // A sanity figure from SOURCES.md: blue-rubber's maximum (all bins) is 35.1, 27.0, 22.6.
  Rgb mx(0.0);
  for (size_t i = 0; i < MerlTable::kBins; ++i) mx = glm::max(mx, t.value(i));
  EXPECT_NEAR(mx.r, 35.1, 0.05);
  EXPECT_NEAR(mx.g, 27.0, 0.05);
  EXPECT_NEAR(mx.b, 22.6, 0.05);
}

}  // namespace glossy::test
