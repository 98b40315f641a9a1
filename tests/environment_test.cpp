// The environment light: orientation and bilinear lookup on small EXR maps written here (expected values
// from the spec's formula, not from the implementation), rotation, importance sampling (pdf consistency,
// normalisation, χ² goodness of fit on half cells, unbiased estimates) on the default sky, the shared
// envmaps and a map of bright panels, nearly equal weights for the samples of a bright texel, the constant
// environment, degenerate inputs, and load errors.
#include "materials/core/input_error.h"
#include "renderer/lights/environment.h"
#include "renderer/lights/latlong.h"
#include "tests/support/chi2.h"
#include "tests/support/render_fixtures.h"
#include "tests/support/test_support.h"

#include <OpenImageIO/imageio.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <tuple>

namespace glossy::test {

namespace {

constexpr double kJustBelowOne = 1.0 - 1e-16;

// The spec's parameterisation, written out independently of the renderer:
// u = atan2(d_x, −d_z)/(2π) wrapped to [0,1), v = acos(d_y)/π.
Vec2 specUv(const Vec3& d) {
  double u = std::atan2(d.x, -d.z) / (2.0 * kPi);
  if (u < 0.0) u += 1.0;
  return {u >= 1.0 ? 0.0 : u, std::acos(std::clamp(d.y, -1.0, 1.0)) / kPi};
}
// Its inverse: θ = πv from +Y, and d_x = sin θ sin φ, d_z = −sin θ cos φ for φ = 2πu.
Vec3 specDirection(double u, double v) {
  const double theta = kPi * v, phi = 2.0 * kPi * u;
  return {std::sin(theta) * std::sin(phi), std::cos(theta), -std::sin(theta) * std::cos(phi)};
}

// Right-handed rotation about +Y (turns +Z towards +X).
Vec3 rotateAboutY(const Vec3& d, double degrees) {
  const double a = degrees * kPi / 180.0, c = std::cos(a), s = std::sin(a);
  return {c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
}

void writeExr(const std::filesystem::path& path, int width, int height, int channels,
              const std::vector<float>& pixels) {
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out) << OIIO::geterror();
  ASSERT_TRUE(out->open(path.string(), OIIO::ImageSpec(width, height, channels, OIIO::TypeDesc::FLOAT)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << out->geterror();
  ASSERT_TRUE(out->close());
}

// An RGB map from a function of (column, row).
template <class F>
std::vector<float> rgbMap(int width, int height, F texel) {
  std::vector<float> pixels;
  for (int row = 0; row < height; ++row)
    for (int column = 0; column < width; ++column) {
      const Rgb c = texel(column, row);
      pixels.insert(pixels.end(), {float(c.r), float(c.g), float(c.b)});
    }
  return pixels;
}

void expectRgbNear(const Rgb& actual, const Rgb& expected, double tolerance, const std::string& where) {
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], tolerance) << where << ", channel " << c;
}

// The message of the InputError that f throws ("" if none).
std::string inputError(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Midpoint rule on an nu × nv grid of (u, v): f(dir, u, v, dω) for each cell; dω = 2π² sin θ du dv.
template <class F>
void forEachDirection(int nu, int nv, F f) {
  for (int j = 0; j < nv; ++j) {
    const double v = (j + 0.5) / nv;
    const double dOmega = 2.0 * kPi * kPi * std::sin(kPi * v) / (double(nu) * nv);
    for (int i = 0; i < nu; ++i) {
      const double u = (i + 0.5) / nu;
      f(specDirection(u, v), u, v, dOmega);
    }
  }
}

// ---------------------------------------------------------------------------------------------------
// Maps for the sampling tests: the default sky, a small map of bright panels (render_fixtures.h), whose
// cells the χ² bins resolve, and each shared envmap that is present.

const std::vector<std::string> kMaps{"default", "panels", "studio_small_09_1k.hdr", "royal_esplanade_1k.hdr",
                                     "quarry_01_1k.hdr"};
// The receiving normals the sampling is tested toward: none (the map's light alone), straight up, one on
// the boundary of two faces of the bins' cube, and a tilted one.
const std::vector<std::pair<std::string, Vec3>> kNormals{
    {"none", Vec3(0.0)}, {"up", Vec3(0, 1, 0)}, {"edge", glm::normalize(Vec3(1, 1, 0))},
    {"tilted", glm::normalize(Vec3(0.3, -0.2, -0.93))}};
// The cases: "map|normal".
std::vector<std::string> samplingCases() {
  std::vector<std::string> cases;
  for (const std::string& map : kMaps)
    for (const auto& [name, normal] : kNormals) cases.push_back(map + "|" + name);
  return cases;
}
Vec3 normalOf(const std::string& testCase) {
  const std::string name = testCase.substr(testCase.find('|') + 1);
  for (const auto& [n, normal] : kNormals)
    if (n == name) return normal;
  return Vec3(0.0);
}
std::string mapOf(const std::string& testCase) { return testCase.substr(0, testCase.find('|')); }
constexpr int kPanelsWidth = 48, kPanelsHeight = 25;

// An environment with the size of its map, which the quadrature below needs to line up with.
struct MapUnderTest {
  std::unique_ptr<Environment> env;
  int width = 0, height = 0;
};

const MapUnderTest* mapFor(const std::string& name) {
  static std::map<std::string, MapUnderTest> cache;
  MapUnderTest& slot = cache[name];
  if (!slot.env) {
    // Rotations by whole texels (1024 columns: 90° = 256, −45° = −128) keep the quadrature aligned.
    if (name == "default") {
      slot = {std::make_unique<Environment>(Environment::makeDefault(90.0)), 1024, 512};
    } else if (name == "panels") {
      const TempDir dir;
      writePanelsMap(dir / "panels.exr", kPanelsWidth, kPanelsHeight);
      slot = {std::make_unique<Environment>(Environment::load(dir / "panels.exr")), kPanelsWidth, kPanelsHeight};
    } else {
      const auto path = sharedDir() / "envmaps" / name;
      auto input = OIIO::ImageInput::open(path.string());
      if (!input) return nullptr;
      slot = {std::make_unique<Environment>(Environment::load(path, -45.0)), input->spec().width,
              input->spec().height};
    }
  }
  return &slot;
}

// Quadrature of the environment's pdf and radiance on a grid lined up with the map: 2 points per column
// and 2 per row interval. The sampling density on the (u, v) square and the bilinear radiance are bilinear
// on each half of a column (texel edge to centre) × half of a row interval, so the midpoint rule is exact
// for the pdf and exact up to the curvature of sin θ for the radiance. χ² bins are whole numbers of those
// pieces, so their expected counts are exact too; on a small map a bin is one piece, and the test sees
// how samples spread within a cell.
struct Quadrature {
  int binsU = 0, binsV = 0;
  double pdfIntegral = 0.0;
  Rgb radianceIntegral{0.0};  // of L cos⁺ θ toward a normal, of L alone for none
  std::vector<double> binProbability;
  // Directions that bring light (L > 0, above the normal's horizon) where the pdf is 0: must be none.
  int lightWithoutDensity = 0;

  std::size_t binOf(Vec2 uv) const {
    return std::size_t(std::min(int(uv.y * binsV), binsV - 1) * binsU + std::min(int(uv.x * binsU), binsU - 1));
  }
};

// A divisor of `cells` near `wanted`, so that bins hold whole cells.
int divisorNear(int cells, int wanted) {
  for (int d = 0; d < wanted; ++d) {
    if (wanted + d <= cells && cells % (wanted + d) == 0) return wanted + d;
    if (wanted - d >= 1 && cells % (wanted - d) == 0) return wanted - d;
  }
  return 1;
}

const Quadrature& quadratureFor(const std::string& name, const MapUnderTest& map, const Vec3& normal) {
  static std::map<std::string, Quadrature> cache;
  if (auto it = cache.find(name); it != cache.end()) return it->second;
  Quadrature q;
  q.binsU = divisorNear(2 * map.width, 48);
  q.binsV = divisorNear(2 * (map.height - 1), 48);
  q.binProbability.assign(std::size_t(q.binsU * q.binsV), 0.0);
  forEachDirection(2 * map.width, 2 * (map.height - 1), [&](const Vec3& d, double u, double v, double dOmega) {
    const double p = map.env->pdf(normal, d) * dOmega;
    q.pdfIntegral += p;
    q.binProbability[q.binOf({u, v})] += p;
    const double cosine = normal == Vec3(0.0) ? 1.0 : std::max(0.0, glm::dot(normal, d));
    const Rgb radiance = map.env->radiance(d);
    q.radianceIntegral += radiance * cosine * dOmega;
    if (cosine > 0.0 && luminance(radiance) > 0.0 && !(p > 0.0)) ++q.lightWithoutDensity;
  });
  return cache.emplace(name, std::move(q)).first->second;
}

// Sampling toward one of kNormals from one of kMaps.
class EnvironmentSampling : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
    const std::string map = mapOf(GetParam());
    if (map != "default" && map != "panels") GLOSSY_REQUIRE_SHARED("envmaps/" + map);
    map_ = mapFor(map);
    ASSERT_NE(map_, nullptr);
    env_ = map_->env.get();
    normal_ = normalOf(GetParam());
  }
  const Quadrature& quadrature() const { return quadratureFor(GetParam(), *map_, normal_); }
  Environment::Sample sample(Vec2 u) const { return env_->sample(normal_, u); }
  double pdf(const Vec3& d) const { return env_->pdf(normal_, d); }
  const MapUnderTest* map_ = nullptr;
  const Environment* env_ = nullptr;
  Vec3 normal_{0.0};
};

std::string mapTestName(const ::testing::TestParamInfo<std::string>& info) {
  const std::string map = mapOf(info.param);
  std::string name = map.substr(0, map.find('.')) + "_" + info.param.substr(info.param.find('|') + 1);
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

}  // namespace

// ---------------------------------------------------------------------------------------------------
// Orientation and lookup

TEST(Environment, SpecFormulaPutsQuarterTurnAtPlusX) {
  // The test's own formula, checked on the axes before it is used to predict the map.
  EXPECT_NEAR(specUv({1, 0, 0}).x, 0.25, 1e-15);
  EXPECT_NEAR(specUv({0, 0, 1}).x, 0.5, 1e-15);
  EXPECT_NEAR(specUv({-1, 0, 0}).x, 0.75, 1e-15);
  EXPECT_NEAR(specUv({0, 0, -1}).x, 0.0, 1e-15);
  EXPECT_NEAR(specUv({0, 1, 0}).y, 0.0, 1e-15);
  EXPECT_NEAR(glm::length(specDirection(0.25, 0.5) - Vec3(1, 0, 0)), 0.0, 1e-15);
}

TEST(Environment, BrightTexelsLightTheDirectionsTheSpecGives) {
  // W = 10 puts texel centres at u = 0.25 (+X, column 2) and 0.75 (−X, column 7); H = 5 puts row 2 on the
  // equator. Rows 0 and 4 are the poles.
  const int w = 10, h = 5;
  const auto pixels = rgbMap(w, h, [](int column, int row) -> Rgb {
    if (row == 0) return {0, 0, 3};
    if (row == 4) return {1, 1, 1};
    if (row != 2) return {0, 0, 0};
    switch (column) {
      case 2: return {5, 0, 0};
      case 7: return {0, 5, 0};
      case 4: return {0, 0, 8};  // u = 0.45; +Z (u = 0.5) is halfway to column 5
      case 9: return {2, 0, 0};  // u = 0.95; −Z (u = 0) is halfway across the seam to column 0
      case 0: return {0, 2, 0};
      default: return {0, 0, 0};
    }
  });
  TempDir dir;
  writeExr(dir / "marks.exr", w, h, 3, pixels);
  const Environment env = Environment::load(dir / "marks.exr");
  EXPECT_EQ(env.description(), "marks.exr");

  expectRgbNear(env.radiance({1, 0, 0}), {5, 0, 0}, 1e-12, "+X");
  expectRgbNear(env.radiance({-1, 0, 0}), {0, 5, 0}, 1e-12, "-X");
  expectRgbNear(env.radiance({0, 0, 1}), {0, 0, 4}, 1e-12, "+Z");
  expectRgbNear(env.radiance({0, 0, -1}), {1, 1, 0}, 1e-12, "-Z");
  expectRgbNear(env.radiance({0, 1, 0}), {0, 0, 3}, 1e-12, "+Y");
  expectRgbNear(env.radiance({0, -1, 0}), {1, 1, 1}, 1e-12, "-Y");

  // The red texel is the brightest red anywhere: scanning the sphere finds its peak at +X.
  double best = -1.0;
  Vec3 bestDir{0.0};
  forEachDirection(360, 180, [&](const Vec3& d, double, double, double) {
    if (const double r = env.radiance(d).r; r > best) best = r, bestDir = d;
  });
  EXPECT_GT(glm::dot(bestDir, Vec3(1, 0, 0)), std::cos(2.0 * kPi / 180.0));
}

// A Radiance .hdr of w × h texels with the resolution line `axes` (e.g. "-Y 4 +X 8"), its scanlines flat
// RGBE in the order stored, each texel dim (1) but for one bright one (8) at stored position (x, y).
void writeHdr(const std::filesystem::path& path, const std::string& axes, int w, int h, int x, int y) {
  std::string bytes = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n" + axes + "\n";
  for (int row = 0; row < h; ++row)
    for (int column = 0; column < w; ++column) {
      const char e = char(column == x && row == y ? 132 : 129);  // 128/256 · 2^(e − 128): 8 or 1
      bytes += std::string{char(128), char(128), char(128), e};
    }
  writeText(path, bytes);
}

// A file may list its rows bottom to top, or its columns right to left, and say so in its header: the map
// is the image as the file shows it, row 0 at the top (+Y). A .hdr written "+Y H +X W" stores its bottom row
// first; read as stored, every feature would land at the mirror latitude.
TEST(Environment, ReadsAFileInTheOrientationItDeclares) {
  const int w = 8, h = 4;
  const TempDir dir;
  const auto brightAt = [&](const std::string& axes, int x, int y) {
    writeHdr(dir / "map.hdr", axes, w, h, x, y);
    const Environment env = Environment::load(dir / "map.hdr");
    int found = 0, column = -1, row = -1;
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i) {
        const Vec2 uv{(i + 0.5) / w, double(j) / (h - 1)};
        if (env.radiance(specDirection(uv.x, uv.y)).r > 4.0) ++found, column = i, row = j;
      }
    EXPECT_EQ(found, 1) << axes;
    return std::pair{column, row};
  };
  EXPECT_EQ(brightAt("-Y 4 +X 8", 2, 1), std::pair(2, 1)) << "top to bottom, as stored";
  EXPECT_EQ(brightAt("+Y 4 +X 8", 2, 1), std::pair(2, 2)) << "bottom row stored first";
  EXPECT_EQ(brightAt("-Y 4 -X 8", 2, 1), std::pair(5, 1)) << "columns right to left";
  EXPECT_EQ(brightAt("+Y 4 -X 8", 2, 1), std::pair(5, 2)) << "both";
}

TEST(Environment, RotationTurnsTheMapRightHandedAboutY) {
  const int w = 10, h = 5;
  const auto pixels = rgbMap(w, h, [](int column, int row) -> Rgb {
    return row == 2 && column == 2 ? Rgb(5, 0, 0) : Rgb(0.1 * column, 0.05 * row, 0.3);
  });
  TempDir dir;
  writeExr(dir / "mark.exr", w, h, 3, pixels);
  const Environment plain = Environment::load(dir / "mark.exr");
  const Environment turned = Environment::load(dir / "mark.exr", 90.0);
  EXPECT_EQ(turned.description(), "mark.exr rotated 90°");

  // A right-handed quarter turn about +Y takes +X to −Z (counter-clockwise seen from above).
  ASSERT_NEAR(glm::length(rotateAboutY({1, 0, 0}, 90.0) - Vec3(0, 0, -1)), 0.0, 1e-15);
  expectRgbNear(turned.radiance({0, 0, -1}), {5, 0, 0}, 1e-12, "-Z after the turn");

  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform;
  for (double degrees : {90.0, 33.0, -120.0}) {
    const Environment env = Environment::load(dir / "mark.exr", degrees);
    for (int k = 0; k < 200; ++k) {
      const Vec3 d = specDirection(uniform(rng), uniform(rng));
      // What the unrotated map shows at d appears at R·d once rotated.
      expectRgbNear(env.radiance(rotateAboutY(d, degrees)), plain.radiance(d), 1e-9, "rotated lookup");
      const Vec3 none(0.0);  // the bins toward a normal do not turn with the map
      EXPECT_NEAR(env.pdf(none, rotateAboutY(d, degrees)), plain.pdf(none, d), 1e-9 * plain.pdf(none, d) + 1e-12);
    }
  }
}

TEST(Environment, BilinearLookupHitsTexelCentresAndInterpolatesAcrossTheSeam) {
  const int w = 6, h = 4;
  std::mt19937_64 rng(3);
  // Float draws: the file holds floats, so the expected values must be floats too.
  std::uniform_real_distribution<float> uniform(0.0f, 4.0f);
  std::vector<Rgb> texels(w * h);
  for (Rgb& t : texels)
    for (int c = 0; c < 3; ++c) t[c] = uniform(rng);
  auto at = [&](int column, int row) { return texels[std::size_t(row * w + ((column % w) + w) % w)]; };
  TempDir dir;
  writeExr(dir / "random.exr", w, h, 3, rgbMap(w, h, at));
  const Environment env = Environment::load(dir / "random.exr");

  const double tolerance = 1e-9;
  // Rows 1 and 2 lie away from the poles, where every column is a distinct direction.
  for (int row = 1; row < h - 1; ++row) {
    const double v = double(row) / (h - 1);
    for (int column = 0; column < w; ++column) {
      const std::string where = "column " + std::to_string(column) + ", row " + std::to_string(row);
      expectRgbNear(env.radiance(specDirection((column + 0.5) / w, v)), at(column, row), tolerance,
                    "centre of " + where);
      // Halfway to the next column (for the last column, across u = 0 to column 0).
      expectRgbNear(env.radiance(specDirection(double(column + 1) / w, v)),
                    0.5 * (at(column, row) + at(column + 1, row)), tolerance, "right of " + where);
      // Halfway to the next row down.
      expectRgbNear(env.radiance(specDirection((column + 0.5) / w, (row + 0.5) / (h - 1))),
                    0.5 * (at(column, row) + at(column, row + 1)), tolerance, "below " + where);
    }
  }
  // A quarter of a column either side of the seam.
  expectRgbNear(env.radiance(specDirection(0.25 / w, 1.0 / 3.0)), 0.75 * at(0, 1) + 0.25 * at(w - 1, 1), tolerance,
                "just right of the seam");
  expectRgbNear(env.radiance(specDirection(1.0 - 0.25 / w, 1.0 / 3.0)), 0.75 * at(w - 1, 1) + 0.25 * at(0, 1),
                tolerance, "just left of the seam");
}

// A fine map looked up through LatLongGrid's batch conversion: the same bilinear values as the spec's
// formula, everywhere, at any rotation.
TEST(Environment, FineMapsLookUpAsTheSpecSays) {
  const int w = 300, h = 160;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<float> texel(0.0f, 4.0f);
  std::vector<Rgb> texels(std::size_t(w) * h);
  for (Rgb& t : texels)
    for (int c = 0; c < 3; ++c) t[c] = texel(rng);
  auto at = [&](int column, int row) { return texels[std::size_t(row * w + ((column % w) + w) % w)]; };
  TempDir dir;
  writeExr(dir / "fine.exr", w, h, 3, rgbMap(w, h, at));
  // Bilinear at (u, v) with texel centres at ((i + ½)/W, j/(H − 1)), written out from the spec.
  auto specLookup = [&](Vec2 uv) {
    const double x = uv.x * w - 0.5, y = uv.y * (h - 1);
    const int i = int(std::floor(x)), j = std::min(int(y), h - 2);
    const double fx = x - i, fy = y - j;
    return (at(i, j) * (1 - fx) + at(i + 1, j) * fx) * (1 - fy) + (at(i, j + 1) * (1 - fx) + at(i + 1, j + 1) * fx) * fy;
  };
  std::uniform_real_distribution<double> uniform;
  for (double degrees : {0.0, 33.0, -120.0}) {
    const Environment env = Environment::load(dir / "fine.exr", degrees);
    for (int k = 0; k < 20000; ++k) {
      // Half of them on texel centres' columns and rows, where a cell ends (not on the poles' rows, whose
      // random texels are not one value for the one direction there).
      double u = uniform(rng), v = uniform(rng);
      if (k % 2) u = (int(u * w) + 0.5) / w, v = double(1 + int(v * (h - 2))) / (h - 1);
      const Vec3 d = rotateAboutY(specDirection(u, v), degrees);
      expectRgbNear(env.radiance(d), specLookup({u, v}), 1e-9, "u = " + std::to_string(u) + ", v = " + std::to_string(v));
    }
  }
}

// LatLongGrid (libmvec, whole batches) against the spec's libm formulas: the same cells and weights (up
// to rounding, and cells differing only on an edge), and direction() inverting position(). Coarse maps
// included, whose cells are wide.
TEST(Environment, GridAgreesWithTheFormulas) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> uniform;
  for (const auto& [w, h, offset] : {std::tuple{1024, 512, 0.0}, std::tuple{2048, 1024, 0.375}, std::tuple{300, 160, 0.9},
                                     std::tuple{8, 4, 0.25}}) {
    const LatLongGrid grid(w, h, offset);
    for (int k = 0; k < 100000; ++k) {
      const double z = 1.0 - 2.0 * uniform(rng), r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * kPi * uniform(rng);
      const Vec3 d = k == 0 ? Vec3(0, 1, 0) : k == 1 ? Vec3(0, -1, 0) : Vec3(r * std::cos(phi), z, r * std::sin(phi));
      const LatLongPosition fast = grid.position(d), exact = latLongPosition(grid.uvOf(d), w, h);
      // The same point: column + fx and row + fy agree, across the seam too.
      const double dx = std::remainder((fast.c0 + fast.fx) - (exact.c0 + exact.fx), double(w));
      ASSERT_NEAR(dx, 0.0, 1e-9) << w << "×" << h << ", " << d.x << " " << d.y << " " << d.z;
      ASSERT_NEAR((fast.r0 + fast.fy) - (exact.r0 + exact.fy), 0.0, 1e-9) << d.x << " " << d.y << " " << d.z;
      if (fast.c0 != exact.c0) {
        ASSERT_TRUE(std::min(fast.fx, exact.fx) < 1e-9 && std::max(fast.fx, exact.fx) > 1 - 1e-9);
      }
      if (fast.r0 != exact.r0) {
        ASSERT_TRUE(std::min(fast.fy, exact.fy) < 1e-9 && std::max(fast.fy, exact.fy) > 1 - 1e-9);
      }
      ASSERT_EQ(fast.c1, (fast.c0 + 1) % w);
      double sinTheta = 0.0;
      const Vec3 back = grid.direction(fast.c0, fast.r0, fast.fx, fast.fy, sinTheta);
      if (std::abs(d.y) < 1.0) {
        ASSERT_NEAR(glm::length(back - d), 0.0, 1e-12) << d.x << " " << d.y << " " << d.z;
      }
      ASSERT_NEAR(sinTheta, std::sqrt(d.x * d.x + d.z * d.z), 1e-12);
    }
  }
}

// LatLongMap against the bilinear formula on the image itself, and the cell's own value, across the seam
// and on the last row of cells.
TEST(Environment, MapLooksUpTheBilinearValueAndTheCellsValue) {
  const int w = 37, h = 11;
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<float> texel(0.0f, 4.0f);
  LatLongImage image(w, h);
  for (int row = 0; row < h; ++row)
    for (int column = 0; column < w; ++column)
      for (int c = 0; c < 3; ++c) image.at(column, row)[c] = texel(rng);
  std::vector<float> values(std::size_t(w) * (h - 1));
  for (float& x : values) x = texel(rng);
  LatLongMap map(image);
  for (int row = 0; row + 1 < h; ++row)
    for (int column = 0; column < w; ++column) map.setCellValue(column, row, values[std::size_t(row) * w + column]);
  std::uniform_real_distribution<double> uniform;
  for (int row = 0; row + 1 < h; ++row)
    for (int column = 0; column < w; ++column)
      for (int k = 0; k < 8; ++k) {
        const int next = (column + 1) % w;
        const LatLongPosition p{column, next, row, k == 0 ? 0.0 : uniform(rng), k == 1 ? 1.0 : uniform(rng)};
        const Rgb expected = (image.texel(column, row) * (1 - p.fx) + image.texel(next, row) * p.fx) * (1 - p.fy) +
                             (image.texel(column, row + 1) * (1 - p.fx) + image.texel(next, row + 1) * p.fx) * p.fy;
        const std::string where = "cell " + std::to_string(column) + ", " + std::to_string(row);
        expectRgbNear(map.interpolate(p), expected, 1e-12, where);
        ASSERT_EQ(map.cellValue(p), values[std::size_t(row) * w + column]) << where;
      }
}

TEST(Environment, ReadsRgbaAndIgnoresAlpha) {
  TempDir dir;
  std::vector<float> pixels;
  for (int i = 0; i < 4 * 2; ++i) pixels.insert(pixels.end(), {0.5f, 1.0f, 2.0f, -7.0f});
  writeExr(dir / "rgba.exr", 4, 2, 4, pixels);
  const Environment env = Environment::load(dir / "rgba.exr");
  expectRgbNear(env.radiance({0.3, 0.5, 0.2}), {0.5, 1.0, 2.0}, 1e-12, "RGBA map");
}

// ---------------------------------------------------------------------------------------------------
// Sampling

// The path tracer's batch forms: lane by lane exactly the one-at-a-time values, whichever lanes are asked.
TEST_P(EnvironmentSampling, BatchFormsEqualTheSingleCalls) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> uniform;
  constexpr int n = Environment::kMaxBatch;
  for (int round = 0; round < 2000; ++round) {
    bool want[n];
    Vec2 u[n];
    Vec3 dirs[n], normals[n];
    const auto randomDirection = [&] {
      const double z = 2.0 * uniform(rng) - 1.0, phi = 2.0 * kPi * uniform(rng), r = std::sqrt(1.0 - z * z);
      return Vec3(r * std::cos(phi), z, r * std::sin(phi));
    };
    for (int i = 0; i < n; ++i) {
      want[i] = (round + i) % 5 != 0;
      u[i] = {uniform(rng), uniform(rng)};
      // Lanes toward this case's normal and lanes toward others, each its own.
      normals[i] = i % 3 == 0 ? normal_ : randomDirection();
      dirs[i] = i % 2 ? randomDirection() : env_->sample(normals[i], u[i]).dir;
    }
    Environment::Sample samples[n];
    Rgb radiance[n];
    double pdf[n];
    env_->sample(want, normals, u, samples, n);
    env_->radianceAndPdf(want, normals, dirs, radiance, pdf, n);
    for (int i = 0; i < n; ++i) {
      if (!want[i]) continue;
      const Environment::Sample one = env_->sample(normals[i], u[i]);
      ASSERT_EQ(samples[i].dir, one.dir);
      ASSERT_EQ(samples[i].radiance, one.radiance);
      ASSERT_EQ(samples[i].pdf, one.pdf);
      double onePdf = 0.0;
      ASSERT_EQ(radiance[i], env_->radianceAndPdf(normals[i], dirs[i], onePdf));
      ASSERT_EQ(pdf[i], onePdf);
    }
  }
}

TEST_P(EnvironmentSampling, PdfIsTheDensitySampleDrawsFrom) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> uniform;
  int invalid = 0;
  for (int k = 0; k < 20000; ++k) {
    const auto s = sample({uniform(rng), uniform(rng)});
    if (s.pdf == 0.0) {
      ++invalid;
      continue;
    }
    ASSERT_NEAR(glm::length(s.dir), 1.0, 1e-12);
    ASSERT_NEAR(pdf(s.dir), s.pdf, 1e-9 * s.pdf);
    const Rgb expected = env_->radiance(s.dir);
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(s.radiance[c], expected[c], 1e-9 * (expected[c] + 1e-6));
    ASSERT_GT(glm::dot(s.radiance, Rgb(1.0)), 0.0) << "sampled a black direction";
  }
  EXPECT_EQ(invalid, 0);
}

// The pdf integrates to 1 over the sphere, and a χ² test finds the samples distributed as it says. The map
// keeps each cell's density in float (beside its texel), so the integral is 1 to float rounding: a cell's
// share is off by at most 2⁻²⁴ of itself (6e-8), the sum by much less.
TEST_P(EnvironmentSampling, PdfIsNormalisedAndSamplesFollowIt) {
  const Quadrature& q = quadrature();
  ASSERT_NEAR(q.pdfIntegral, 1.0, 3e-8);
  EXPECT_EQ(q.lightWithoutDensity, 0) << "directions that bring light but cannot be sampled";
  const int n = 200000;
  std::vector<double> observed(q.binProbability.size(), 0.0);
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> uniform;
  for (int k = 0; k < n; ++k) {
    const auto s = sample({uniform(rng), uniform(rng)});
    ASSERT_GT(s.pdf, 0.0);
    observed[q.binOf(specUv(s.dir))] += 1.0;
  }
  // Pearson's χ², pooling the bins expected to hold fewer than 5 samples.
  double chi2 = 0.0, pooledObserved = 0.0, pooledExpected = 0.0;
  int bins = 0;
  for (std::size_t b = 0; b < observed.size(); ++b) {
    const double expected = q.binProbability[b] * n;
    if (expected == 0.0) {
      ASSERT_EQ(observed[b], 0.0) << "samples in bin " << b << " where the pdf is 0";
    }
    if (expected < 5.0) {
      pooledObserved += observed[b];
      pooledExpected += expected;
      continue;
    }
    chi2 += (observed[b] - expected) * (observed[b] - expected) / expected;
    ++bins;
  }
  if (pooledExpected >= 5.0) {
    chi2 += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
    ++bins;
  }
  const int dof = bins - 1;
  const double p = chi2Survival(chi2, dof);
  std::cout << "χ² test on " << GetParam() << ": χ² = " << chi2 << ", dof = " << dof << ", p = " << p << "\n";
  RecordProperty("chi2_p_value", std::to_string(p));
  EXPECT_GT(p, 0.01) << "χ² = " << chi2 << " with " << dof << " degrees of freedom";
}

// Toward a normal the integral of L cos⁺ θ (the surface's irradiance), without one that of L.
TEST_P(EnvironmentSampling, EstimatesTheIntegralOfRadianceWithoutBias) {
  const Rgb reference = quadrature().radianceIntegral;
  const int n = 200000;
  Rgb sum{0.0};
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> uniform;
  for (int k = 0; k < n; ++k) {
    const auto s = sample({uniform(rng), uniform(rng)});
    const double cosine = normal_ == Vec3(0.0) ? 1.0 : std::max(0.0, glm::dot(normal_, s.dir));
    if (s.pdf > 0.0) sum += s.radiance * (cosine / s.pdf);
  }
  const Rgb estimate = sum / double(n);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(estimate[c], reference[c], 0.01 * reference[c]) << "channel " << c;
}

TEST_P(EnvironmentSampling, NoNanAtTheEndsOfTheSquareOrThePoles) {
  for (double a : {0.0, 0.5, kJustBelowOne, 1.0})
    for (double b : {0.0, 1e-300, 0.5, kJustBelowOne, 1.0}) {
      const auto s = sample({a, b});
      EXPECT_TRUE(std::isfinite(s.pdf) && s.pdf >= 0.0) << a << ", " << b;
      if (s.pdf > 0.0) {
        EXPECT_TRUE(std::isfinite(s.dir.x) && std::isfinite(s.dir.y) && std::isfinite(s.dir.z));
        EXPECT_TRUE(std::isfinite(glm::dot(s.radiance, Rgb(1.0))));
      }
    }
  for (const Vec3& d : {Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(1e-300, 1, 0), Vec3(0, -1, -1e-300),
                        glm::normalize(Vec3(1e-9, 1, 1e-9))}) {
    const double p = pdf(d);
    EXPECT_TRUE(std::isfinite(p) && p >= 0.0) << d.x << " " << d.y << " " << d.z;
    EXPECT_TRUE(std::isfinite(glm::dot(env_->radiance(d), Rgb(1.0))));
  }
}

INSTANTIATE_TEST_SUITE_P(Maps, EnvironmentSampling, ::testing::ValuesIn(samplingCases()), mapTestName);

// Drawn by the bilinear function of its cell's corners' luminance × sin θ, a light sample's luminance over
// its pdf is nearly the same wherever it lands in a bright texel's cells (a density constant over each
// cell gives 0 to 4 times the mean there). Nearly, as the interpolated product is not the product of the
// interpolations: where one corner outshines the others, its row's sin θ stands for the whole cell, off by
// up to Δθ·cot θ (1.2 % at 45° on this 512 × 257 map, a row apart being 0.7°). The density follows
// luminance × sin θ everywhere, so the ratio is close to the map's whole integral of luminance; the dim
// sky's cells are left out, as they keep the floor share every lit patch has (compact_cdf.h).
TEST(Environment, SamplesOfABrightTexelCarryNearlyEqualWeights) {
  constexpr int kWidth = 512, kHeight = 257;
  const TempDir dir;
  writePanelsMap(dir / "panels.exr", kWidth, kHeight);
  const Environment env = Environment::load(dir / "panels.exr");
  double integral = 0.0;
  forEachDirection(2 * kWidth, 2 * (kHeight - 1),
                   [&](const Vec3& d, double, double, double dOmega) { integral += luminance(env.radiance(d)) * dOmega; });
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uniform;
  double lowest = 1e300, highest = 0.0;
  int bright = 0;
  for (int k = 0; k < 100000; ++k) {
    const auto s = env.sample(Vec3(0.0), {uniform(rng), uniform(rng)});
    ASSERT_GT(s.pdf, 0.0);
    if (luminance(s.radiance) < 2.0 || std::abs(s.dir.y) > 0.99) continue;  // in the dim sky, or by a pole
    const double ratio = luminance(s.radiance) / s.pdf / integral;
    lowest = std::min(lowest, ratio);
    highest = std::max(highest, ratio);
    ++bright;
  }
  ASSERT_GT(bright, 3000);
  std::cout << bright << " samples of bright texels: L/pdf from " << lowest << " to " << highest << " of the integral\n";
  EXPECT_GT(lowest, 0.98);
  EXPECT_LT(highest, 1.02);
}

// ---------------------------------------------------------------------------------------------------
// Constant and default environments

// Toward a surface the constant environment is sampled by cos θ about its normal, L cos θ itself: the
// estimate of the irradiance π L is exact at every sample, and nothing is drawn below the horizon.
TEST(Environment, ConstantTowardASurfaceIsCosineWeighted) {
  const Environment env = Environment::constant({0.5, 0.25, 1.0});
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> uniform;
  for (const Vec3& normal : {Vec3(0, 1, 0), glm::normalize(Vec3(0.3, -0.2, -0.93)), Vec3(0, 0, -1)}) {
    for (int k = 0; k < 2000; ++k) {
      const auto s = env.sample(normal, {uniform(rng), uniform(rng)});
      ASSERT_GT(s.pdf, 0.0);
      ASSERT_NEAR(glm::length(s.dir), 1.0, 1e-12);
      const double cosine = glm::dot(normal, s.dir);
      ASSERT_GT(cosine, 0.0);
      ASSERT_NEAR(s.pdf, cosine / kPi, 1e-12);
      ASSERT_DOUBLE_EQ(env.pdf(normal, s.dir), s.pdf);
      const Rgb irradiance = s.radiance * (cosine / s.pdf);
      ASSERT_NEAR(irradiance.b, kPi, 1e-9);
    }
    EXPECT_EQ(env.pdf(normal, -normal), 0.0);
  }
}

TEST(Environment, ConstantIsUniformAndSampledUniformly) {
  const Environment env = Environment::constant({0.5, 0.25, 1.0});
  EXPECT_EQ(env.description(), "constant 0.5,0.25,1");
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> uniform;
  Vec3 mean{0.0};
  const int n = 20000;
  const Vec3 none(0.0);
  for (int k = 0; k < n; ++k) {
    const auto s = env.sample(none, {uniform(rng), uniform(rng)});
    EXPECT_DOUBLE_EQ(s.pdf, 1.0 / (4.0 * kPi));
    EXPECT_NEAR(glm::length(s.dir), 1.0, 1e-12);
    EXPECT_EQ(s.radiance, Rgb(0.5, 0.25, 1.0));
    mean += s.dir / double(n);
  }
  EXPECT_LT(glm::length(mean), 0.03);  // no preferred direction
  for (double a : {0.0, kJustBelowOne, 1.0})
    for (double b : {0.0, kJustBelowOne, 1.0}) {
      const auto s = env.sample(none, {a, b});
      EXPECT_NEAR(glm::length(s.dir), 1.0, 1e-12);
    }
  for (const Vec3& d : {Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0.6, 0, 0.8)}) {
    EXPECT_EQ(env.radiance(d), Rgb(0.5, 0.25, 1.0));
    EXPECT_DOUBLE_EQ(env.pdf(none, d), 1.0 / (4.0 * kPi));
  }
  EXPECT_NE(inputError([] { Environment::constant({-1, 0, 0}); }), "");
}

TEST(Environment, DefaultSkyLightsAGreyDiffuseSurfaceModerately) {
  const Environment env = Environment::makeDefault();
  EXPECT_EQ(env.description(), "default sky");
  EXPECT_EQ(Environment::makeDefault(-45).description(), "default sky rotated -45°");

  // E(n)/π is what a white Lambertian surface facing n reflects.
  auto reflected = [&](const Vec3& n) {
    double sum = 0.0;
    forEachDirection(512, 256, [&](const Vec3& d, double, double, double dOmega) {
      const Rgb L = env.radiance(d);
      sum += (0.2126 * L.r + 0.7152 * L.g + 0.0722 * L.b) * std::max(0.0, glm::dot(n, d)) * dOmega;
    });
    return sum / kPi;
  };
  double mean = 0.0;
  for (const Vec3& n : {Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1), Vec3(0, 0, -1)}) {
    const double r = reflected(n);
    std::cout << "default sky: white diffuse facing (" << n.x << ", " << n.y << ", " << n.z << ") reflects " << r
              << "\n";
    EXPECT_GT(r, 0.05);
    EXPECT_LT(r, 1.2);
    mean += r / 6.0;
  }
  EXPECT_GT(mean, 0.3);
  EXPECT_LT(mean, 0.8);
}

// ---------------------------------------------------------------------------------------------------
// Errors

TEST(Environment, LoadErrorsNameTheFileOnOneLine) {
  TempDir dir;
  writeText(dir / "text.exr", "this is not an image\n");
  writeExr(dir / "nan.exr", 2, 2, 3, {1, 1, 1, 1, std::nanf(""), 1, 1, 1, 1, 1, 1, 1});
  writeExr(dir / "negative.exr", 2, 2, 3, {1, 1, 1, 1, 1, 1, 1, -0.5f, 1, 1, 1, 1});
  writeExr(dir / "inf.exr", 2, 2, 3, {1, 1, 1, 1, 1, 1, 1, 1, 1, INFINITY, 1, 1});
  writeExr(dir / "grey.exr", 2, 2, 2, std::vector<float>(8, 1.0f));

  const std::map<std::string, std::string> problems{{"missing.exr", "not found"},
                                                    {"text.exr", "cannot read"},
                                                    {"nan.exr", "not finite"},
                                                    {"inf.exr", "not finite"},
                                                    {"negative.exr", "negative"},
                                                    {"grey.exr", "channel"}};
  for (const auto& [name, problem] : problems) {
    const auto path = dir / name;
    const std::string message = inputError([&] { Environment::load(path); });
    EXPECT_NE(message.find(path.string()), std::string::npos) << name << ": " << message;
    EXPECT_NE(message.find(problem), std::string::npos) << name << ": " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << name << ": " << message;
  }
  EXPECT_NE(inputError([] { Environment::makeDefault(std::nan("")); }), "");
}

}  // namespace glossy::test
