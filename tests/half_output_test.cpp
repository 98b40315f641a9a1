// Image files hold no Inf or NaN: half output clamps to the largest finite half (65504) and float output
// to float's largest, NaN is written as 0, and the pixels so changed are counted in the metadata; the
// renders behind `render --half` and `sheet --half` under a very bright sky show it.
#include "renderer/util/notes.h"
#include "renderer/image/exr_image.h"
#include "tests/support/test_support.h"

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <limits>

namespace glossy::test {

namespace {

// Every channel of every layer of an EXR.
std::vector<float> allChannels(const std::filesystem::path& exr) {
  auto in = OIIO::ImageInput::open(exr.string());
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> v(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, v.data())) return {};
  return v;
}

void expectFiniteAtMost(const std::vector<float>& values, float largest) {
  ASSERT_FALSE(values.empty());
  for (float v : values) {
    ASSERT_TRUE(std::isfinite(v));
    ASSERT_LE(std::abs(v), largest);
  }
}

}  // namespace

TEST(HalfOutput, WriterClampsInfinityAndZeroesNaNCountingThePixels) {
  takeNotes();  // what earlier tests of this process noted is not this test's
  RgbImage img(2, 2);
  const float inf = std::numeric_limits<float>::infinity();
  const float values[4][3] = {{inf, 1, 1}, {std::nanf(""), 0, 0}, {1e5f, 1, -inf}, {1, 1, 1}};
  for (int p = 0; p < 4; ++p)
    for (int c = 0; c < 3; ++c) img.pixels[size_t(p) * 3 + c] = values[p][c];
  TempDir tmp;
  writeExr(tmp / "h.exr", img, {}, PixelType::Half);
  expectFiniteAtMost(allChannels(tmp / "h.exr"), kLargestHalf);
  EXPECT_EQ(readImageAttribute(tmp / "h.exr", "glossy:halfClampedPixels"), "3");
  // Said, not only recorded: one note, with the count.
  const std::vector<std::string> notes = takeNotes();
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_EQ(notes[0], (tmp / "h.exr").string() + ": 3 of 4 pixels had a value above 65504, the largest half, written as 65504 "
                                                 "(a float EXR keeps them)");
  EXPECT_EQ(readRgbImage(tmp / "h.exr").pixels[0], kLargestHalf);
  EXPECT_EQ(readRgbImage(tmp / "h.exr").pixels[3], 0.0f);

  writeExr(tmp / "f.exr", img, {}, PixelType::Float);
  expectFiniteAtMost(allChannels(tmp / "f.exr"), std::numeric_limits<float>::max());
  EXPECT_EQ(readImageAttribute(tmp / "f.exr", "glossy:nonFinitePixels"), "3");
  // A float EXR clips only what is not finite: counted, and said too.
  const std::vector<std::string> floatNotes = takeNotes();
  ASSERT_EQ(floatNotes.size(), 1u);
  EXPECT_EQ(floatNotes[0], (tmp / "f.exr").string() + ": 3 of 4 pixels were not finite (an overflow or a NaN), written as the largest float or 0");
  EXPECT_EQ(readRgbImage(tmp / "f.exr").pixels[6], 1e5f);

  img.pixels.assign(img.pixels.size(), 0.5f);
  writeExr(tmp / "ok.exr", img, {}, PixelType::Half);
  EXPECT_TRUE(takeNotes().empty()) << "nothing clipped, nothing said";
  EXPECT_EQ(readImageAttribute(tmp / "ok.exr", "glossy:halfClampedPixels"), "0");
  writeExr(tmp / "ok-float.exr", img, {}, PixelType::Float);
  EXPECT_EQ(readImageAttribute(tmp / "ok-float.exr", "glossy:nonFinitePixels"), "");
}

TEST(HalfOutput, RenderAndSheetUnderABrightSkyWriteFiniteHalves) {
  TempDir tmp;
  const RunResult r = runGlossy({"render", "--width", "12", "--height", "12", "--spp", "2", "--env-constant", "1e6", "--half",
                                 "-o", (tmp / "r.exr").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  expectFiniteAtMost(allChannels(tmp / "r.exr"), kLargestHalf);
  EXPECT_GT(std::stoi(readImageAttribute(tmp / "r.exr", "glossy:halfClampedPixels")), 0);
  EXPECT_NE(r.err.find("r.exr: " + readImageAttribute(tmp / "r.exr", "glossy:halfClampedPixels") +
                       " of 144 pixels had a value above 65504"),
            std::string::npos)
      << r.err;

  const RunResult s = runGlossy({"sheet", "--material", (materialsDir() / "chrome.toml").string(), "--width", "12", "--height",
                                 "12", "--spp", "2", "--env-constant", "1e6", "--half", "-o", (tmp / "s.exr").string()});
  ASSERT_EQ(s.status, 0) << s.err;
  expectFiniteAtMost(allChannels(tmp / "s.exr"), kLargestHalf);
  EXPECT_GT(std::stoi(readImageAttribute(tmp / "s.exr", "glossy:halfClampedPixels")), 0);
  EXPECT_NE(s.err.find("s.exr: " + readImageAttribute(tmp / "s.exr", "glossy:halfClampedPixels") + " of "), std::string::npos)
      << s.err;
}

}  // namespace glossy::test
