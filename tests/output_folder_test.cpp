// Folders glossy fills (renderer/output/owned_folder.h): glossy plot's -o and glossy report's site carry a
// manifest of what glossy wrote there. A folder that is not glossy's own is refused before any work; in its
// own folder a run replaces only what the manifest lists and keeps every other file; a run cut short by a
// signal leaves no temporary behind and every glossy file listed.
#include "renderer/output/owned_folder.h"
#include "materials/core/text.h"
#include "tests/support/test_support.h"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>

namespace glossy::test {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> listed(const fs::path& folder) {
  return nlohmann::json::parse(readText(folder / OwnedFolder::kManifest))["files"].get<std::vector<std::string>>();
}

void writeFolder(OwnedFolder& folder, const std::vector<std::string>& files) {
  folder.plan(files);
  for (const std::string& f : files) {
    fs::create_directories(folder.path(f).parent_path());
    writeText(folder.path(f), "glossy's " + f);
  }
  folder.finish();
}

}  // namespace

TEST(OutputFolder, AFolderGlossyDidNotFillIsRefused) {
  TempDir tmp;
  fs::create_directories(tmp / "user");
  writeText(tmp / "user/thesis.tex", "mine");
  EXPECT_NE(expectInputError([&] { OwnedFolder(tmp / "user", "glossy plot", "-o"); }).find("-o " + (tmp / "user").string()), std::string::npos);
  writeText(tmp / "file", "x");
  expectInputError([&] { OwnedFolder(tmp / "file", "glossy plot", "-o"); });
  expectInputError([&] { OwnedFolder("/", "glossy plot", "-o"); });
  // Another command's folder, or a manifest that is not glossy's.
  OwnedFolder plots(tmp / "plots", "glossy plot", "-o");
  writeFolder(plots, {"plots.json"});
  EXPECT_NE(expectInputError([&] { OwnedFolder(tmp / "plots", "glossy report", "-o"); }).find("glossy plot"), std::string::npos);
  for (const char* manifest : {"not json", R"({"command": "glossy plot"})", R"({"command": "glossy plot", "files": ["../thesis.tex"]})",
                               R"({"command": "glossy plot", "files": ["/etc/passwd"]})", R"({"command": "glossy plot", "files": [".hidden"]})"}) {
    writeText(tmp / "plots" / OwnedFolder::kManifest, manifest);
    expectInputError([&] { OwnedFolder(tmp / "plots", "glossy plot", "-o"); });
  }
  fs::remove(tmp / "plots" / OwnedFolder::kManifest);
  fs::create_symlink(tmp / "elsewhere.json", tmp / "plots" / OwnedFolder::kManifest);
  writeText(tmp / "elsewhere.json", R"({"command": "glossy plot", "files": []})");
  expectInputError([&] { OwnedFolder(tmp / "plots", "glossy plot", "-o"); });
  EXPECT_EQ(readText(tmp / "user/thesis.tex"), "mine");
}

TEST(OutputFolder, ARunReplacesOnlyWhatGlossyWrote) {
  TempDir tmp;
  {
    OwnedFolder f(tmp / "out", "glossy report", "-o");
    writeFolder(f, {"index.html", "materials/a/index.html", "materials/b/index.html"});
  }
  writeText(tmp / "out/notes.txt", "the user's");
  writeText(tmp / "out/materials/b/mine.txt", "the user's too");
  {
    OwnedFolder f(tmp / "out", "glossy report", "-o");
    writeFolder(f, {"index.html", "materials/c/index.html"});
  }
  EXPECT_EQ(listed(tmp / "out"), (std::vector<std::string>{"index.html", "materials/c/index.html"}));
  EXPECT_EQ(readText(tmp / "out/notes.txt"), "the user's");
  EXPECT_EQ(readText(tmp / "out/materials/b/mine.txt"), "the user's too");
  EXPECT_FALSE(fs::exists(tmp / "out/materials/b/index.html"));
  EXPECT_FALSE(fs::exists(tmp / "out/materials/a")) << "a folder the removal left empty goes too";
  // A file glossy would write that is there but not listed: refused, not overwritten; nothing is written.
  writeText(tmp / "out/materials/d.html", "the user's");
  OwnedFolder f(tmp / "out", "glossy report", "-o");
  EXPECT_NE(expectInputError([&] { f.plan({"index.html", "materials/d.html"}); }).find("materials/d.html"), std::string::npos);
  EXPECT_EQ(readText(tmp / "out/materials/d.html"), "the user's");
  EXPECT_EQ(listed(tmp / "out"), (std::vector<std::string>{"index.html", "materials/c/index.html"}));
  // A folder on the way replaced by a symlink is not written or deleted through.
  fs::create_directories(tmp / "elsewhere");
  writeText(tmp / "elsewhere/index.html", "not glossy's");
  fs::remove_all(tmp / "out/materials/c");
  fs::create_symlink(tmp / "elsewhere", tmp / "out/materials/c");
  OwnedFolder g(tmp / "out", "glossy report", "-o");
  expectInputError([&] { g.plan({"materials/c/index.html"}); });
  g.plan({"index.html"});
  g.finish();
  EXPECT_EQ(readText(tmp / "elsewhere/index.html"), "not glossy's");
}

// glossy plot -o / wrote plots.json and its figures into /.
TEST(OutputFolder, PlotWritesOnlyIntoItsOwnFolder) {
  TempDir tmp;
  auto plot = [&](const fs::path& out) {
    return runGlossy({"plot", "--material", (materialsDir() / "chrome.toml").string(), "--figures", "albedo", "-o", out.string()});
  };
  fs::create_directories(tmp / "user");
  writeText(tmp / "user/thesis.tex", "mine");
  expectOneLineError(plot(tmp / "user"), "-o " + (tmp / "user").string());
  EXPECT_EQ(fs::directory_iterator(tmp / "user")->path().filename(), "thesis.tex");
  expectOneLineError(plot("/"), "-o /");
  EXPECT_FALSE(fs::exists("/plots.json"));

  RunResult r = plot(tmp / "plots");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> files = listed(tmp / "plots");
  EXPECT_NE(std::find(files.begin(), files.end(), "plots.json"), files.end());
  EXPECT_NE(std::find(files.begin(), files.end(), "albedo.svg"), files.end());
  writeText(tmp / "plots/README", "the user's");
  r = plot(tmp / "plots");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readText(tmp / "plots/README"), "the user's");
  // glossy report takes a plot folder as plots, never as its site.
  expectOneLineError(runGlossy({"report", (tmp / "none").string(), "-o", (tmp / "plots").string()}), "glossy plot");
}

// An interrupted report leaves no temporary (a hidden site folder, a .tmp file) and every glossy file listed,
// so the next run replaces it.
TEST(OutputFolder, AnInterruptedReportLeavesNothingBehind) {
  TempDir tmp;
  // Forty materials: long enough to be stopped in the middle.
  const fs::path sheets = tmp / "sheets";
  RunResult r = runGlossy({"sheet", "--material", (materialsDir() / "chrome.toml").string(), "--width", "16", "--height", "16", "--spp", "4",
                           "-o", (tmp / "one/chrome.exr").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string exr = readText(tmp / "one/chrome.exr"), png = readText(tmp / "one/chrome.png");
  fs::create_directories(sheets);
  for (int k = 0; k < 40; ++k) {
    // The material's name is in the header; a rename of the attribute's value keeps the file's length.
    std::string copy = exr;
    const std::string name = "chrome", other = formatted("m%04d", k);
    size_t at = copy.find(std::string("glossy:materialName"));
    ASSERT_NE(at, std::string::npos);
    at = copy.find(name, at);
    ASSERT_NE(at, std::string::npos);
    ASSERT_EQ(other.size(), 5u);
    copy.replace(at, name.size(), other + "-");  // "chrome" -> "m0007-": six bytes for six
    writeText(sheets / (other + ".exr"), copy);
    writeText(sheets / (other + ".png"), png);
  }
  // A whole run's length, then runs stopped at points through it: the first making the site, the others
  // replacing it.
  const auto start = std::chrono::steady_clock::now();
  r = runGlossy({"report", sheets.string(), "-o", (tmp / "timing").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fs::remove_all(tmp / "timing");
  const std::string site = (tmp / "site").string();
  for (double fraction : {0.5, 0.1, 0.3, 0.7, 0.9}) {
    SCOPED_TRACE(fraction);
    const std::string cmd = shellQuote(GLOSSY_EXE) + " report " + shellQuote(sheets.string()) + " -o " + shellQuote(site) +
                            " 2>/dev/null & p=$!; sleep " + formatted("%.3f", fraction * seconds) + "; kill -TERM $p 2>/dev/null; wait $p";
    std::system(cmd.c_str());
    for (const auto& e : fs::recursive_directory_iterator(tmp.path())) {
      const std::string name = e.path().filename().string();
      EXPECT_EQ(name.find(".tmp"), std::string::npos) << e.path();
    }
    if (fs::exists(tmp / "site" / OwnedFolder::kManifest)) {
      const std::vector<std::string> files = listed(tmp / "site");
      for (const auto& e : fs::recursive_directory_iterator(tmp / "site")) {
        if (!e.is_regular_file() || e.path().filename() == OwnedFolder::kManifest) continue;
        EXPECT_NE(std::find(files.begin(), files.end(), e.path().lexically_relative(tmp / "site").string()), files.end()) << e.path();
      }
    }
  }
  r = runGlossy({"report", sheets.string(), "-o", site});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::is_regular_file(tmp / "site/materials/m0039-/index.html"));
}

}  // namespace glossy::test
