// glossy sheets' resuming (renderer/app/sheet_resume.h): a sheet on disk is kept only if its EXR opens,
// has every layer and carries this run's settings; broken or foreign sheets are rendered again, things in
// the way and clashing names stop the run before any rendering, and one run at a time writes each sheet.
#include "renderer/image/exr_image.h"
#include "tests/support/test_support.h"

#include <algorithm>
#include <functional>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace glossy::test {

namespace {

struct Batch {
  TempDir tmp;
  Batch() {
    std::filesystem::create_directories(tmp / "lib");
    for (const char* name : {"chrome", "gold-paint"})
      std::filesystem::copy_file(materialsDir() / (std::string(name) + ".toml"), tmp / "lib" / (std::string(name) + ".toml"));
  }
  std::filesystem::path out(const std::string& file = "") const { return file.empty() ? tmp / "out" : tmp / "out" / file; }
  RunResult run(std::vector<std::string> extra = {}) const {
    std::vector<std::string> args{"sheets", (tmp / "lib").string(), "-o", out().string(), "--merl-dir", tmp.path().string(),
                                  "--width", "16", "--height", "16", "--spp", "4"};
    args.insert(args.end(), extra.begin(), extra.end());
    return runGlossy(args);
  }
};

bool mentions(const RunResult& r, const std::string& s) { return r.err.find(s) != std::string::npos; }

}  // namespace

TEST(CliSheetsResume, BrokenSheetsAreRenderedAgain) {
  Batch b;
  ASSERT_EQ(b.run().status, 0);
  EXPECT_FALSE(readImageAttribute(b.out("chrome.exr"), "glossy:settings").empty());
  const RunResult again = b.run();
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_TRUE(mentions(again, "chrome: complete, skipped")) << again.err;
  EXPECT_TRUE(mentions(again, "gold-paint: complete, skipped")) << again.err;

  writeText(b.out("chrome.exr"), "");  // 0 bytes
  const std::string whole = readText(b.out("gold-paint.exr"));
  writeText(b.out("gold-paint.exr"), whole.substr(0, whole.size() / 2));  // cut short
  const RunResult r = b.run();
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(mentions(r, "chrome: unreadable EXR")) << r.err;
  EXPECT_TRUE(mentions(r, "gold-paint: unreadable EXR")) << r.err;
  EXPECT_TRUE(mentions(r, "2 sheets rendered")) << r.err;
  for (const char* sheet : {"chrome.exr", "gold-paint.exr"}) EXPECT_NO_THROW(readImageLayer(b.out(sheet), "measured")) << sheet;
}

TEST(CliSheetsResume, ASheetAtOtherSettingsOrOfAnEditedMaterialIsRenderedAgain) {
  Batch b;
  ASSERT_EQ(b.run().status, 0);
  RunResult r = b.run({"--seed", "7"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(mentions(r, "chrome: made with other settings")) << r.err;
  EXPECT_TRUE(mentions(r, "2 sheets rendered")) << r.err;

  writeText(b.tmp / "lib" / "chrome.toml", readText(b.tmp / "lib" / "chrome.toml") + "# edited\n");
  r = b.run({"--seed", "7"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(mentions(r, "chrome: made with other settings")) << r.err;
  EXPECT_TRUE(mentions(r, "gold-paint: complete, skipped")) << r.err;
  EXPECT_TRUE(mentions(r, "1 sheets rendered")) << r.err;

  // A sheet of an older format (before the error maps: its settings say no format) is made again.
  const std::string settings = readImageAttribute(b.out("gold-paint.exr"), "glossy:settings");
  ASSERT_NE(settings.find("; format="), std::string::npos) << settings;
  writeExr(b.out("gold-paint.exr"), readRgbImage(b.out("gold-paint.exr")),
           {{"glossy:settings", settings.substr(0, settings.find("; format="))}});
  r = b.run({"--seed", "7"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(mentions(r, "gold-paint: made with other settings")) << r.err;
  EXPECT_TRUE(mentions(r, "chrome: complete, skipped")) << r.err;
}

// Sheets of other panels are not trusted, even when they have as many (the PNG's size matches) and the
// layers this run asks for.
TEST(CliSheetsResume, ASheetOfOtherPanelsIsRenderedAgain) {
  Batch b;
  ASSERT_EQ(b.run({"--panels", "measured,microfacet:E2,cook-torrance:E1"}).status, 0);
  RunResult r = b.run({"--panels", "microfacet:E2,measured,cook-torrance:E1"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(mentions(r, "chrome: made with other settings")) << r.err;
  EXPECT_EQ(readImageAttribute(b.out("chrome.exr"), "glossy:panels"), "microfacet_E2,measured,cook_torrance_E1");
  r = b.run({"--panels", "microfacet:E2,measured,cook-torrance:E1"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(mentions(r, "chrome: complete, skipped")) << r.err;
  r = b.run();  // the default grid: seven panels
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(mentions(r, "2 sheets rendered")) << r.err;
  EXPECT_NO_THROW(readImageLayer(b.out("chrome.exr"), "smooth_E2"));
}

TEST(CliSheetsResume, AFolderInTheWayOrTwoFilesOfOneNameStopBeforeRendering) {
  Batch b;
  std::filesystem::create_directories(b.out("chrome.exr"));
  expectOneLineError(b.run(), (b.out("chrome.exr")).string());
  EXPECT_FALSE(std::filesystem::exists(b.out("gold-paint.exr")));
  std::filesystem::remove(b.out("chrome.exr"));

  writeText(b.tmp / "lib" / "chrome-copy.toml", readText(b.tmp / "lib" / "chrome.toml"));
  const RunResult r = b.run();
  expectOneLineError(r, "chrome-copy.toml");
  EXPECT_TRUE(mentions(r, (b.tmp / "lib" / "chrome.toml").string())) << r.err;
  EXPECT_FALSE(std::filesystem::exists(b.out("gold-paint.exr")));
}

TEST(CliSheetsResume, ASheetAnotherRunIsWritingIsLeftToItAndStaleTemporariesAreCleaned) {
  Batch b;
  std::filesystem::create_directories(b.out());
  // What a killed run of glossy leaves (atomic_file.h names them), and a user's files named like an older
  // pattern, which are not glossy's to delete.
  writeText(b.out("chrome.exr.tmp.glossy-abc123"), "half a sheet");
  writeText(b.out("gold-paint.png.tmp.glossy-def456"), "half a preview");
  writeText(b.out("chrome.exr.tmp.abc123"), "a user's file");
  writeText(b.out("gold-paint.png.tmp.glossy-def456.keep"), "a user's file");
  // Another run holds chrome's lock: its temporaries are its own, and the sheet is its to write.
  const int fd = ::open(b.out(".chrome.exr.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  RunResult r = b.run();
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_TRUE(mentions(r, "chrome: -o: " + b.out("chrome.exr").string() + " is being written by another glossy process, skipped"))
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(b.out("chrome.exr")));
  EXPECT_TRUE(std::filesystem::exists(b.out("chrome.exr.tmp.glossy-abc123")));
  EXPECT_FALSE(std::filesystem::exists(b.out("gold-paint.png.tmp.glossy-def456")));
  EXPECT_TRUE(std::filesystem::exists(b.out("gold-paint.exr")));
  EXPECT_FALSE(std::filesystem::exists(b.out(".gold-paint.exr.lock"))) << "a lock is not left behind";
  ::close(fd);

  r = b.run();
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(std::filesystem::exists(b.out("chrome.exr.tmp.glossy-abc123")));
  EXPECT_TRUE(mentions(r, "chrome: removed 1 temporary")) << r.err;
  EXPECT_TRUE(std::filesystem::exists(b.out("chrome.exr")));
  EXPECT_EQ(readText(b.out("chrome.exr.tmp.abc123")), "a user's file");
  EXPECT_EQ(readText(b.out("gold-paint.png.tmp.glossy-def456.keep")), "a user's file");
}

// A PNG is trusted only if it opens as a PNG of the size the settings give: text under the name or a PNG
// of another size is rendered again, not kept.
TEST(CliSheetsResume, APngThatIsNotThisSheetsPngIsRenderedAgain) {
  Batch b;
  ASSERT_EQ(b.run().status, 0);
  const std::string png = readText(b.out("chrome.png"));
  writeText(b.out("chrome.png"), "not a PNG at all");
  writeRgb8(b.out("gold-paint.png"), 16, 16, std::vector<unsigned char>(16 * 16 * 3, 128));
  RunResult r = b.run();
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(mentions(r, "chrome: PNG that is not a PNG image, rendering it again")) << r.err;
  EXPECT_TRUE(mentions(r, "gold-paint: PNG of 16x16, not the")) << r.err;
  EXPECT_TRUE(mentions(r, "2 sheets rendered")) << r.err;
  EXPECT_EQ(readText(b.out("chrome.png")).substr(0, 8), png.substr(0, 8));
}


// A sheet's settings carry everything its pixels depend on: not the environment map's or the scene's name
// alone but their contents (a map of the same name in another folder, a map or a glTF buffer edited in
// place), the camera, and each number at full precision (a rotation changed in its seventh digit).
TEST(CliSheetsResume, ASheetOfOtherSceneOrLightingContentIsRenderedAgain) {
  Batch b;
  const auto lightMap = [](const std::filesystem::path& path, float value) {
    std::filesystem::create_directories(path.parent_path());
    RgbImage map(16, 8);
    std::fill(map.pixels.begin(), map.pixels.end(), value);
    writeExr(path, map, {});
  };
  const auto expectRenderedAgain = [&](const std::vector<std::string>& before, const std::vector<std::string>& after,
                                       const std::function<void()>& change = {}) {
    ASSERT_EQ(b.run(before).status, 0);
    if (change) change();
    const RunResult r = b.run(after);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(mentions(r, "chrome: made with other settings")) << r.err;
    EXPECT_TRUE(mentions(r, "2 sheets rendered")) << r.err;
  };
  {
    SCOPED_TRACE("a map of the same name in another folder, then one edited in place");
    lightMap(b.tmp / "a/studio.exr", 0.5f);
    lightMap(b.tmp / "b/studio.exr", 0.7f);
    expectRenderedAgain({"--env", (b.tmp / "a/studio.exr").string()}, {"--env", (b.tmp / "b/studio.exr").string()});
    expectRenderedAgain({"--env", (b.tmp / "a/studio.exr").string()}, {"--env", (b.tmp / "a/studio.exr").string()},
                        [&] { lightMap(b.tmp / "a/studio.exr", 0.6f); });
  }
  {
    SCOPED_TRACE("a rotation changed in its seventh digit");
    expectRenderedAgain({"--env-rotate", "10"}, {"--env-rotate", "10.000004"});
  }
  {
    SCOPED_TRACE("a constant changed in its seventh digit");
    expectRenderedAgain({"--env-constant", "0.8"}, {"--env-constant", "0.80000004"});
  }
  {
    SCOPED_TRACE("a glTF buffer edited in place, then another camera");
    std::filesystem::create_directories(b.tmp / "scene");
    for (const char* f : {"sphere.gltf", "sphere.bin"}) std::filesystem::copy_file(sourceDir() / "scenes" / f, b.tmp / "scene" / f);
    const std::string scene = (b.tmp / "scene/sphere.gltf").string();
    expectRenderedAgain({"--scene", scene}, {"--scene", scene}, [&] {
      std::string bin = readText(b.tmp / "scene/sphere.bin");
      bin[100620] = char(bin[100620] ^ 1);  // the first normal's x, by one unit in the last place
      writeText(b.tmp / "scene/sphere.bin", bin);
    });
    expectRenderedAgain({"--scene", scene}, {"--scene", scene, "--camera", "ortho"});
  }
}

}  // namespace glossy::test
