// HDR-ꟻLIP (renderer/image/flip.h): properties any correct implementation has (zero for identical images,
// values in [0,1] for any input, mirror/transpose symmetry, invariance to a common scale, a closed form on
// uniform images), and the validation against NVIDIA's flip-evaluator (tests/flip/reference_flip.py, run
// with the test Python): synthetic HDR pairs and panels of the reference sheets, written as EXR, each
// pair's mean within 1e-3 of the package's and its map close pixel by pixel. Skipped, saying why, where
// the test Python or flip_evaluator is absent.
#include "renderer/image/flip.h"
#include "renderer/image/masked_mean.h"
#include "renderer/sheet/sheet.h"
#include "tests/support/image_regression.h"
#include "tests/support/test_python.h"
#include "tests/support/test_support.h"


#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <time.h>

namespace glossy::test {

namespace {

// A scene-like HDR image: a smooth coloured backdrop around 0.1-0.5, shaded discs, and small highlights
// 4-7 stops above 1.
RgbImage scene(int w, int h, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  RgbImage img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      float* p = img.at(x, y);
      p[0] = 0.1f + 0.4f * float(x) / float(w);
      p[1] = 0.15f + 0.3f * float(y) / float(h);
      p[2] = 0.3f - 0.2f * float(x + y) / float(w + h);
    }
  for (int d = 0; d < 6; ++d) {
    const float cx = u(rng) * float(w), cy = u(rng) * float(h), radius = (0.1f + 0.15f * u(rng)) * float(std::min(w, h));
    const float colour[3] = {0.2f + 0.8f * u(rng), 0.2f + 0.8f * u(rng), 0.2f + 0.8f * u(rng)};
    const float peak = std::exp2(4.0f + 3.0f * u(rng));
    const float hx = cx - 0.3f * radius, hy = cy - 0.3f * radius;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const float r2 = ((float(x) - cx) * (float(x) - cx) + (float(y) - cy) * (float(y) - cy)) / (radius * radius);
        if (r2 > 1.0f) continue;
        const float shade = std::sqrt(1.0f - r2);
        const float h2 = ((float(x) - hx) * (float(x) - hx) + (float(y) - hy) * (float(y) - hy)) / (0.04f * radius * radius);
        const float highlight = peak * std::exp(-h2);
        float* p = img.at(x, y);
        for (int c = 0; c < 3; ++c) p[c] = colour[c] * shade + highlight;
      }
  }
  return img;
}

template <class F>
RgbImage mapPixels(const RgbImage& src, F f) {
  RgbImage out = src;
  for (int y = 0; y < src.height; ++y)
    for (int x = 0; x < src.width; ++x) f(x, y, out.at(x, y));
  return out;
}

RgbImage withNoise(const RgbImage& src, float relative, uint32_t seed, bool allowNegative = false) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> n(0.0f, 1.0f);
  return mapPixels(src, [&](int, int, float* p) {
    for (int c = 0; c < 3; ++c) {
      p[c] += relative * (p[c] + 0.05f) * n(rng);
      if (!allowNegative) p[c] = std::max(p[c], 0.0f);
    }
  });
}

RgbImage boxBlur(const RgbImage& src) {
  return mapPixels(src, [&](int x, int y, float* p) {
    for (int c = 0; c < 3; ++c) {
      float s = 0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
          s += src.at(std::clamp(x + dx, 0, src.width - 1), std::clamp(y + dy, 0, src.height - 1))[c];
      p[c] = s / 9.0f;
    }
  });
}

RgbImage shifted(const RgbImage& src, int dx, int dy) {
  return mapPixels(src, [&](int x, int y, float* p) {
    const float* q = src.at(std::clamp(x - dx, 0, src.width - 1), std::clamp(y - dy, 0, src.height - 1));
    std::copy(q, q + 3, p);
  });
}

RgbImage mirrored(const RgbImage& src) {
  return mapPixels(src, [&](int x, int y, float* p) {
    const float* q = src.at(src.width - 1 - x, y);
    std::copy(q, q + 3, p);
  });
}

RgbImage transposed(const RgbImage& src) {
  RgbImage out(src.height, src.width);
  for (int y = 0; y < src.height; ++y)
    for (int x = 0; x < src.width; ++x) std::copy(src.at(x, y), src.at(x, y) + 3, out.at(y, x));
  return out;
}

RgbImage uniform(int w, int h, float r, float g, float b) {
  RgbImage img(w, h);
  for (size_t i = 0; i < img.pixels.size(); i += 3) img.pixels[i] = r, img.pixels[i + 1] = g, img.pixels[i + 2] = b;
  return img;
}

// A sheet panel of a reference sheet in tests/reference/.
RgbImage referencePanel(const std::string& material, const std::string& layer) {
  const auto panels = sheetPanels();
  const auto it = std::find_if(panels.begin(), panels.end(), [&](const SheetPanel& p) { return p.layer == layer; });
  const RgbImage full = readImageLayer(sourceDir() / "tests/reference" / (material + ".exr"), layer);
  const int size = full.width / int(panels.size());
  return crop(full, int(it - panels.begin()) * size, 0, size, full.height);
}

// ---- A closed form on uniform images, written from the papers independently of flip.cpp. ----

double aces(double x) {  // Narkowicz's fit, after HDR-ꟻLIP's 0.6 pre-exposure
  const double v = 0.6 * x;
  return v * (2.51 * v + 0.03) / (v * (2.43 * v + 0.59) + 0.14);
}
struct Lab {
  double l, a, b;
};
Lab huntLab(const double rgb[3]) {
  // IEC 61966-2-1 (sRGB, D65) to XYZ; the white is the row sums.
  const double m[3][3] = {{0.4124, 0.3576, 0.1805}, {0.2126, 0.7152, 0.0722}, {0.0193, 0.1192, 0.9505}};
  double f[3];
  for (int i = 0; i < 3; ++i) {
    const double t = (m[i][0] * rgb[0] + m[i][1] * rgb[1] + m[i][2] * rgb[2]) / (m[i][0] + m[i][1] + m[i][2]);
    f[i] = t > std::pow(6.0 / 29.0, 3) ? std::cbrt(t) : t / (3.0 * std::pow(6.0 / 29.0, 2)) + 4.0 / 29.0;
  }
  const double l = 116.0 * f[1] - 16.0;
  return {l, 0.01 * l * 500.0 * (f[0] - f[1]), 0.01 * l * 200.0 * (f[1] - f[2])};
}
double hyab(const Lab& p, const Lab& q) { return std::fabs(p.l - q.l) + std::hypot(p.a - q.a, p.b - q.b); }

// HDR-ꟻLIP of uniform colour b against uniform colour a: both exposures bring a's luminance to x_max (where
// ACES gives 0.85); the filters leave uniform images unchanged and the feature detectors see nothing.
double uniformFlip(const double a[3], const double b[3]) {
  double lo = 0.0, hi = 100.0;
  for (int i = 0; i < 200; ++i) (aces(0.5 * (lo + hi)) < 0.85 ? lo : hi) = 0.5 * (lo + hi);
  const double xMax = 0.5 * (lo + hi), m = xMax / (0.2126 * a[0] + 0.7152 * a[1] + 0.0722 * a[2]);
  double ta[3], tb[3];
  for (int c = 0; c < 3; ++c) ta[c] = std::min(1.0, aces(a[c] * m)), tb[c] = std::min(1.0, aces(b[c] * m));
  const double green[3] = {0, 1, 0}, blue[3] = {0, 0, 1};
  const double cmax = std::pow(hyab(huntLab(green), huntLab(blue)), 0.7), knee = 0.4 * cmax;
  const double e = std::pow(hyab(huntLab(ta), huntLab(tb)), 0.7);
  return e < knee ? 0.95 * e / knee : 0.95 + 0.05 * (e - knee) / (cmax - knee);
}

}  // namespace

TEST(FlipProperties, IdenticalImagesScoreZeroEverywhere) {
  const RgbImage a = scene(96, 64, 1);
  const FlipMap map = hdrFlip(a, a);
  ASSERT_EQ(map.width, 96);
  ASSERT_EQ(map.height, 64);
  ASSERT_EQ(map.error.size(), size_t(96 * 64));
  for (float v : map.error) ASSERT_EQ(v, 0.0f);
  EXPECT_EQ(map.mean, 0.0);
}

TEST(FlipProperties, DifferentImagesScoreAndTheMeanIsTheMapsMean) {
  const RgbImage a = scene(96, 64, 2), b = withNoise(a, 0.2f, 3);
  const FlipMap map = hdrFlip(a, b);
  double sum = 0;
  for (float v : map.error) sum += v;
  EXPECT_NEAR(map.mean, sum / double(map.error.size()), 1e-9);
  EXPECT_GT(map.mean, 0.05);  // 20 % noise is plainly visible
  EXPECT_LT(map.mean, 0.6);
}

TEST(FlipProperties, MapIsFiniteAndInTheUnitIntervalForHostileInput) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const float hostile[] = {nan, inf, -inf, -1e3f, -0.5f, 1e30f, std::numeric_limits<float>::max(), 1e-40f, 0.0f, 65504.0f};
  std::mt19937 rng(4);
  std::uniform_int_distribution<int> pick(0, int(std::size(hostile)) - 1);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  RgbImage a = scene(48, 40, 5), b = a;
  for (float& v : b.pixels)
    if (u(rng) < 0.3f) v = hostile[pick(rng)];
  RgbImage hostileRef = b;
  const RgbImage black(48, 40);
  using Pair = std::pair<const RgbImage*, const RgbImage*>;
  for (const auto& [ref, test] : {Pair{&a, &b}, Pair{&hostileRef, &a}, Pair{&black, &a}, Pair{&black, &black}, Pair{&hostileRef, &hostileRef}}) {
    const FlipMap map = hdrFlip(*ref, *test);
    for (float v : map.error) {
      ASSERT_TRUE(std::isfinite(v));
      ASSERT_GE(v, 0.0f);
      ASSERT_LE(v, 1.0f);
    }
    EXPECT_TRUE(std::isfinite(map.mean));
    const FlipExposures e = hdrFlipExposures(*ref);
    EXPECT_TRUE(std::isfinite(e.start) && std::isfinite(e.stop));
    EXPECT_LE(e.start, e.stop);
    EXPECT_GE(e.count, 2);
  }
}

// flip-evaluator clamps each tone-mapped channel to [0,1] with NaN going to 0; an infinite channel, or one
// whose exposed square overflows, tone maps to ∞/∞ = NaN: all of them count as black.
TEST(FlipProperties, NonFiniteAndOverflowingTestPixelsCountAsBlack) {
  const RgbImage a = scene(64, 48, 6);
  RgbImage black = a;
  black.at(20, 20)[0] = 0.0f;
  const FlipMap expected = hdrFlip(a, black);
  for (float v : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), 1e30f}) {
    RgbImage b = a;
    b.at(20, 20)[0] = v;
    const FlipMap map = hdrFlip(a, b);
    EXPECT_EQ(map.error, expected.error) << "value " << v;
  }
  // …while a merely large value is white, not black.
  RgbImage white = a;
  white.at(20, 20)[0] = 1e6f;
  EXPECT_NE(hdrFlip(a, white).error, expected.error);
}

// The filters are symmetric and the edges clamped alike on every side, so mirroring or transposing both
// images mirrors or transposes the map (to float rounding: the taps are summed in another order).
TEST(FlipProperties, MirroringAndTransposingCommuteWithTheMap) {
  const RgbImage a = scene(80, 56, 7), b = shifted(withNoise(a, 0.1f, 8), 1, 0);
  const FlipMap map = hdrFlip(a, b);
  const FlipMap mirror = hdrFlip(mirrored(a), mirrored(b));
  const FlipMap transpose = hdrFlip(transposed(a), transposed(b));
  ASSERT_EQ(transpose.width, 56);
  double worstMirror = 0, worstTranspose = 0;
  for (int y = 0; y < 56; ++y)
    for (int x = 0; x < 80; ++x) {
      const float v = map.error[size_t(y) * 80 + size_t(x)];
      worstMirror = std::max(worstMirror, double(std::fabs(v - mirror.error[size_t(y) * 80 + size_t(79 - x)])));
      worstTranspose = std::max(worstTranspose, double(std::fabs(v - transpose.error[size_t(x) * 56 + size_t(y)])));
    }
  EXPECT_LT(worstMirror, 1e-4);
  EXPECT_LT(worstTranspose, 1e-4);
  EXPECT_GT(map.mean, 0.01);
}

// The exposures come from the reference's luminances, so scaling both images by s shifts them by −log2 s
// and leaves every tone-mapped image, hence the map, as it was.
TEST(FlipProperties, ScalingBothImagesChangesNothing) {
  const RgbImage a = scene(64, 64, 9), b = boxBlur(a);
  auto scaled = [](const RgbImage& img, float s) {
    return mapPixels(img, [&](int, int, float* p) {
      for (int c = 0; c < 3; ++c) p[c] *= s;
    });
  };
  const FlipMap map = hdrFlip(a, b), map8 = hdrFlip(scaled(a, 8.0f), scaled(b, 8.0f));
  const FlipExposures e = hdrFlipExposures(a), e8 = hdrFlipExposures(scaled(a, 8.0f));
  EXPECT_NEAR(e8.start, e.start - 3.0f, 1e-5);
  EXPECT_NEAR(e8.stop, e.stop - 3.0f, 1e-5);
  EXPECT_EQ(e8.count, e.count);
  for (size_t i = 0; i < map.error.size(); ++i) ASSERT_NEAR(map.error[i], map8.error[i], 1e-4) << "pixel " << i;
  EXPECT_GT(map.mean, 0.01);
}

TEST(FlipProperties, UniformImagesMatchTheClosedForm) {
  const double cases[][2][3] = {{{3.2, 0.8, 0.4}, {0.6, 1.5, 2.7}},
                                {{0.5, 0.5, 0.5}, {0.51, 0.5, 0.49}},
                                {{20.0, 18.0, 15.0}, {2.0, 1.8, 1.5}},
                                {{0.01, 0.3, 0.02}, {0.01, 0.02, 0.3}}};
  for (const auto& c : cases) {
    const RgbImage a = uniform(24, 20, float(c[0][0]), float(c[0][1]), float(c[0][2]));
    const RgbImage b = uniform(24, 20, float(c[1][0]), float(c[1][1]), float(c[1][2]));
    const double expected = uniformFlip(c[0], c[1]);
    const FlipMap map = hdrFlip(a, b);
    EXPECT_EQ(hdrFlipExposures(a).count, 2);
    for (float v : map.error) ASSERT_NEAR(v, expected, 2e-3) << c[0][0] << " vs " << c[1][0];
  }
}

TEST(FlipProperties, RejectsBadArguments) {
  const RgbImage a = scene(16, 16, 10), b = scene(16, 12, 10);
  EXPECT_THROW(hdrFlip(a, b), std::invalid_argument);
  EXPECT_THROW(hdrFlip(RgbImage(), RgbImage()), std::invalid_argument);
  RgbImage broken = a;
  broken.pixels.pop_back();
  EXPECT_THROW(hdrFlip(a, broken), std::invalid_argument);
  for (double ppd : {0.0, -67.0, std::nan(""), 1e6}) EXPECT_THROW(hdrFlip(a, a, FlipSettings{ppd}), std::invalid_argument);
}

// The extremes of the viewing condition: filters a fraction of a pixel wide (whose off-centre taps
// underflow) and filters wider than the image.
TEST(FlipProperties, ExtremeViewingConditionsStayFinite) {
  const RgbImage a = scene(40, 30, 22), b = withNoise(a, 0.2f, 23);
  for (double ppd : {0.05, 1.0, 1000.0}) {
    const FlipMap map = hdrFlip(a, b, FlipSettings{ppd});
    for (float v : map.error) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f && v <= 1.0f) << "ppd " << ppd;
    EXPECT_GT(map.mean, 0.0) << "ppd " << ppd;
    EXPECT_EQ(hdrFlip(a, a, FlipSettings{ppd}).mean, 0.0) << "ppd " << ppd;
  }
}

TEST(FlipProperties, MaskedMeanAveragesTheMaskedPixels) {
  FlipMap map;
  map.width = 2, map.height = 2;
  map.error = {0.1f, 0.2f, 0.4f, 0.8f};
  EXPECT_NEAR(maskedMean(map.error, {1, 0, 1, 0}), 0.25, 1e-7);
  EXPECT_NEAR(maskedMean(map.error, {1, 1, 1, 1}), 0.375, 1e-7);
  EXPECT_EQ(maskedMean(map.error, {0, 0, 0, 0}), 0.0);
  EXPECT_THROW(maskedMean(map.error, {1, 1}), std::invalid_argument);
}


// The validation: flip-evaluator's HDR-ꟻLIP on the same EXR files.
TEST(FlipReference, MatchesFlipEvaluator) {
  if (!std::filesystem::exists(testPython()))
    GTEST_SKIP() << "the test Python " << testPython() << " is absent (scripts/test-tools creates it)";
  TempDir tmp;
  ScriptRun check = runTestPython(tmp, "tests/flip/reference_flip.py", {"--check"});
  while (!check.err.empty() && std::isspace(static_cast<unsigned char>(check.err.back()))) check.err.pop_back();
  if (check.status != 0) GTEST_SKIP() << "flip_evaluator is not importable by " << testPython() << ": " << check.err;

  const RgbImage base = scene(160, 120, 13), sheet = scene(256, 256, 14);
  // More than half the reference black: its median luminance is 0, which flip-evaluator ≥ 1.7 floors.
  const RgbImage mostlyBlack = mapPixels(base, [](int x, int, float* p) {
    if (x < 100) p[0] = p[1] = p[2] = 0.0f;
  });
  // Negative and huge values in the test image, as a buggy render could give.
  std::mt19937 rng(15);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const RgbImage hostile = mapPixels(withNoise(base, 0.05f, 16, true), [&](int, int, float* p) {
    const float r = u(rng);
    if (r < 0.01f) p[0] = -5.0f;
    else if (r < 0.02f) p[1] = 1e30f;
  });
  struct Pair {
    std::string name;
    RgbImage reference, test;
  };
  std::vector<Pair> pairs = {
      {"noise 10 %", base, withNoise(base, 0.1f, 17)},
      {"box blur 3x3", base, boxBlur(base)},
      {"colour shift", base, mapPixels(base, [](int, int, float* p) { p[0] *= 1.15f, p[2] *= 0.85f; })},
      {"one-pixel shift", base, shifted(base, 1, 0)},
      {"highlights 1.5 stops dimmer", base, mapPixels(base, [](int, int, float* p) {
         for (int c = 0; c < 3; ++c)
           if (p[c] > 2.0f) p[c] = 2.0f + (p[c] - 2.0f) * 0.35f;
       })},
      {"mostly black reference", mostlyBlack, withNoise(mostlyBlack, 0.1f, 18)},
      {"negative and huge test pixels", base, hostile},
      {"256x256, noise 5 % + shift", sheet, shifted(withNoise(sheet, 0.05f, 19), 0, 1)},
      {"chrome: measured vs CT E2", referencePanel("chrome", "measured"), referencePanel("chrome", "cook_torrance_E2")},
      {"gold-paint: measured vs AS E1", referencePanel("gold-paint", "measured"), referencePanel("gold-paint", "ashikhmin_shirley_E1")},
      {"blue-acrylic: measured vs smooth E2", referencePanel("blue-acrylic", "measured"), referencePanel("blue-acrylic", "smooth_E2")},
  };

  const FlipSettings settings;
  std::vector<std::string> args = {std::to_string(settings.pixelsPerDegree)};
  for (size_t i = 0; i < pairs.size(); ++i) {
    const std::string stem = "pair" + std::to_string(i);
    writeExr(tmp / (stem + "_ref.exr"), pairs[i].reference, {}, PixelType::Float);
    writeExr(tmp / (stem + "_test.exr"), pairs[i].test, {}, PixelType::Float);
    for (const char* s : {"_ref.exr", "_test.exr", "_map.f32"}) args.push_back((tmp / (stem + s)).string());
  }
  const ScriptRun run = runTestPython(tmp, "tests/flip/reference_flip.py", args);
  ASSERT_EQ(run.status, 0) << run.err;
  std::istringstream lines(run.out);
  double worstMean = 0, worstPixel = 0;
  for (size_t i = 0; i < pairs.size(); ++i) {
    const Pair& p = pairs[i];
    double theirMean = 0, theirStart = 0, theirStop = 0;
    int theirCount = 0;
    ASSERT_TRUE(lines >> theirMean >> theirStart >> theirStop >> theirCount) << "script output:\n" << run.out;
    // What the package reads back from the EXR: writeExr leaves finite floats as they are.
    const FlipMap ours = hdrFlip(p.reference, p.test, settings);
    const FlipExposures e = hdrFlipExposures(p.reference);
    EXPECT_EQ(e.count, theirCount) << p.name;
    EXPECT_NEAR(e.start, theirStart, 1e-4) << p.name;
    EXPECT_NEAR(e.stop, theirStop, 1e-4) << p.name;
    EXPECT_NEAR(ours.mean, theirMean, 1e-3) << p.name;
    const std::vector<float> theirs = readFloats(tmp / ("pair" + std::to_string(i) + "_map.f32"), ours.error.size());
    double pixel = 0;
    for (size_t j = 0; j < theirs.size(); ++j) pixel = std::max(pixel, double(std::fabs(theirs[j] - ours.error[j])));
    EXPECT_LT(pixel, 5e-4) << p.name;  // float rounding gives under 1e-4
    worstMean = std::max(worstMean, std::fabs(ours.mean - theirMean));
    worstPixel = std::max(worstPixel, pixel);
    std::printf("%-38s %3dx%-3d exposures %2d  flip-evaluator %.6f  glossy %.6f  diff %+.2e  max pixel diff %.2e\n",
                p.name.c_str(), p.reference.width, p.reference.height, theirCount, theirMean, ours.mean, ours.mean - theirMean,
                pixel);
  }
  RecordProperty("worst_mean_difference", std::to_string(worstMean));
  RecordProperty("worst_pixel_difference", std::to_string(worstPixel));
}

}  // namespace glossy::test
