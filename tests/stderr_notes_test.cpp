// What glossy prints on stderr: every line starts with "glossy: ", and the notes that loading input makes
// (unmeasured bins of a table, primitives a scene loader skipped) never come before an error, which must
// be a bad-input run's only line.
#include "tests/support/test_support.h"

#include <sstream>

namespace glossy::test {

namespace {

// A triangle, drawn once as POINTS (which the loader skips with a note) and once as TRIANGLES, and a camera.
std::string mixedScene() {
  return R"({"asset": {"version": "2.0"},
  "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "mode": 0}, {"attributes": {"POSITION": 0}}]}],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.01}}],
  "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0.3, 0.3, 3]}],
  "scenes": [{"nodes": [0, 1]}], "scene": 0})";
}

void expectEveryLinePrefixed(const std::string& err) {
  std::istringstream lines(err);
  for (std::string line; std::getline(lines, line);) EXPECT_EQ(line.rfind("glossy: ", 0), 0u) << line;
}

}  // namespace

TEST(StderrNotes, UnmeasuredBinsNoteNeverPrecedesAnError) {
  TempDir tmp;
  const std::string holes = (tmp / "holes.binary").string();
  writeText(holes, syntheticMerlBytes([](int h, int, int) { return h == 0 ? Rgb(-1.0) : Rgb(300.0); }));
  const std::vector<std::string> render = {"render", "--measured", holes, "--width", "8", "--height", "8", "--spp", "1",
                                           "-o", (tmp / "x.exr").string()};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = render;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  expectOneLineError(runGlossy(with({"--env-constant", "x"})), "--env-constant");
  expectOneLineError(runGlossy(with({"--camera", "nope"})), "nope");
  expectOneLineError(runGlossy({"eval", "--measured", holes}, "0.3,0,0.954,-0.3,0,0.954\nnot,a,pair\n"), "");
  expectOneLineError(runGlossy({"sheet", "--material", (materialsDir() / "chrome.toml").string(), "--measured", holes,
                                "--camera", "nope", "-o", (tmp / "x.exr").string()}),
                     "nope");
  EXPECT_FALSE(std::filesystem::exists(tmp / "x.exr"));

  // A good run still says so, and first.
  const RunResult ok = runGlossy(render);
  ASSERT_EQ(ok.status, 0) << ok.err;
  EXPECT_EQ(ok.err.rfind("glossy: " + holes + ": 16200 of 1458000 bins unmeasured", 0), 0u) << ok.err;
  expectEveryLinePrefixed(ok.err);
}

TEST(StderrNotes, SkippedPrimitivesNoteIsPrefixedAndNeverPrecedesAnError) {
  TempDir tmp;
  writeText(tmp / "mixed.gltf", mixedScene());
  const std::vector<std::string> render = {"render", "--scene", (tmp / "mixed.gltf").string(), "--width", "8", "--height", "8",
                                           "--spp", "1", "-o", (tmp / "x.exr").string()};
  const RunResult ok = runGlossy(render);
  ASSERT_EQ(ok.status, 0) << ok.err;
  EXPECT_NE(ok.err.find("mixed.gltf: warning: skipped 1 primitive"), std::string::npos) << ok.err;
  expectEveryLinePrefixed(ok.err);

  std::vector<std::string> bad = render;
  bad.insert(bad.end(), {"--camera", "nope"});
  expectOneLineError(runGlossy(bad), "no camera named 'nope'");
}

}  // namespace glossy::test

namespace glossy::test {

// A note about an input is told once a run, not once for each sheet that reads the input: a study of 177
// sheets printed a table's unmeasured bins 177 times.
TEST(StderrNotes, ANoteAboutAnInputIsToldOncePerRun) {
  TempDir tmp;
  writeText(tmp / "holes.binary", syntheticMerlBytes([](int h, int, int) { return h == 0 ? Rgb(-1.0) : Rgb(300.0); }));
  std::filesystem::create_directories(tmp / "lib");
  std::string chrome = readText(materialsDir() / "chrome.toml");
  chrome.replace(chrome.find("measured = \"chrome.binary\""), 26, "measured = \"holes.binary\"");
  for (const char* name : {"one", "two"}) {
    std::string m = chrome;
    m.replace(m.find("name = \"chrome\""), 15, "name = \"" + std::string(name) + "\"");
    writeText(tmp / "lib" / (std::string(name) + ".toml"), m);
  }
  const RunResult r = runGlossy({"sheets", (tmp / "lib").string(), "-o", (tmp / "out").string(), "--merl-dir", tmp.path().string(),
                                 "--width", "8", "--height", "8", "--spp", "1", "--panels", "measured,microfacet:E2"});
  ASSERT_EQ(r.status, 0) << r.err;
  const size_t first = r.err.find("bins unmeasured");
  ASSERT_NE(first, std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("bins unmeasured", first + 1), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("2 sheets rendered"), std::string::npos) << r.err;
  expectEveryLinePrefixed(r.err);
}

}  // namespace glossy::test
