// One rule finds measured data in every command (resolveMeasured, docs/measured.md): a --measured name is
// looked for under --merl-dir, then $GLOSSY_MERL_DIR, then the working folder — eval and sample as render
// (sheet's and fit's are tested with them, in sheet_cli_test and fit_cli_test).
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sys/stat.h>

namespace glossy::test {

namespace {

// $GLOSSY_MERL_DIR for the glossy runs of one scope (they inherit the test's environment).
class MerlDirVariable {
 public:
  explicit MerlDirVariable(const std::filesystem::path& dir) {
    if (const char* v = std::getenv("GLOSSY_MERL_DIR")) saved_ = v, had_ = true;
    ::setenv("GLOSSY_MERL_DIR", dir.c_str(), 1);
  }
  ~MerlDirVariable() {
    if (had_) ::setenv("GLOSSY_MERL_DIR", saved_.c_str(), 1);
    else ::unsetenv("GLOSSY_MERL_DIR");
  }

 private:
  std::string saved_;
  bool had_ = false;
};

// Each command that reads --measured, with what it needs besides.
std::vector<std::vector<std::string>> commandsWith(const std::string& measured, const std::filesystem::path& out) {
  return {{"eval", "--measured", measured},
          {"sample", "--measured", measured, "--wo", "0,0,1", "-n", "2"},
          {"render", "--measured", measured, "--width", "8", "--height", "8", "--spp", "1", "-o", (out / "r.exr").string()}};
}

}  // namespace

TEST(MeasuredResolution, EveryCommandLooksUnderMerlDirAndTheVariable) {
  TempDir tmp;
  std::filesystem::create_directories(tmp / "merl");
  std::filesystem::copy_file(materialsDir() / "chrome.nbrdf", tmp / "merl/network.nbrdf");
  // Not found as given (the tests run elsewhere): an error naming it, for every command alike.
  for (const auto& args : commandsWith("network.nbrdf", tmp.path())) {
    SCOPED_TRACE(args[0]);
    expectOneLineError(runGlossy(args, "0,0,1,0,0,1\n"), "network.nbrdf: measured data not found");
  }
  for (auto args : commandsWith("network.nbrdf", tmp.path())) {
    SCOPED_TRACE(args[0] + " --merl-dir");
    args.insert(args.begin() + 1, {"--merl-dir", (tmp / "merl").string()});
    const RunResult r = runGlossy(args, "0,0,1,0,0,1\n");
    EXPECT_EQ(r.status, 0) << r.err;
  }
  const MerlDirVariable variable(tmp / "merl");
  for (const auto& args : commandsWith("network.nbrdf", tmp.path())) {
    SCOPED_TRACE(args[0] + " $GLOSSY_MERL_DIR");
    const RunResult r = runGlossy(args, "0,0,1,0,0,1\n");
    EXPECT_EQ(r.status, 0) << r.err;
  }
}

// The same name gives the same values whichever way it was found.
TEST(MeasuredResolution, EvalOfANameFoundUnderMerlDirIsEvalOfThePath) {
  TempDir tmp;
  std::filesystem::create_directories(tmp / "merl");
  std::filesystem::copy_file(materialsDir() / "chrome.nbrdf", tmp / "merl/network.nbrdf");
  const std::string pairs = "0,0,1,0,0,1\n0.3,0,0.95,-0.3,0,0.95\n";
  const RunResult byPath = runGlossy({"eval", "--measured", (tmp / "merl/network.nbrdf").string()}, pairs);
  const RunResult byName = runGlossy({"eval", "--measured", "network.nbrdf", "--merl-dir", (tmp / "merl").string()}, pairs);
  ASSERT_EQ(byPath.status, 0) << byPath.err;
  ASSERT_EQ(byName.status, 0) << byName.err;
  EXPECT_EQ(byName.out, byPath.out);
}

// A --merl-dir that is not a folder — missing, a file, a FIFO — is refused by every command that takes it,
// in one line naming the option and the path, and so is $GLOSSY_MERL_DIR; before, each was passed over in
// silence and the tables looked for elsewhere (renderer/cli/main.cpp, checkMerlDirs).
TEST(MeasuredResolution, AMerlDirThatIsNotAFolderIsRefused) {
  TempDir tmp;
  writeText(tmp / "file", "not a folder");
  ASSERT_EQ(::mkfifo((tmp / "fifo").c_str(), 0600), 0);
  writeText(tmp / "study.toml", "materials = \"merl/chrome\"\n[lightings]\nsky = { sky = true }\n");
  const std::string chrome = (materialsDir() / "chrome.toml").string();
  const std::string out = (tmp / "out").string();
  const std::map<std::string, std::vector<std::string>> commands = {
      {"error", {"error", "--material", chrome}},
      {"eval", {"eval", "--material", chrome, "--fit", "smooth:E2"}},
      {"fit", {"fit", "--measured", "chrome.nbrdf", "--model", "cook-torrance", "--metric", "E2", "-o", out + "/fit.toml"}},
      {"list", {"list"}},
      {"plot", {"plot", "--material", chrome, "-o", out + "/plots"}},
      {"render", {"render", "--material", chrome, "--fit", "smooth:E2", "--spp", "1", "-o", out + "/r.exr"}},
      {"sample", {"sample", "--material", chrome, "--fit", "smooth:E2", "--wo", "0,0,1", "-n", "2"}},
      {"sheet", {"sheet", "--material", chrome, "--width", "8", "--height", "8", "--spp", "1", "-o", out + "/s.exr"}},
      {"sheets", {"sheets", chrome, "--width", "8", "--height", "8", "--spp", "1", "-o", out + "/sheets"}},
      {"study", {"study", (tmp / "study.toml").string(), "-o", out + "/study"}},
  };
  // Every command whose help offers --merl-dir is in the table.
  for (const char* c : {"error", "eval", "fit", "import", "list", "merge", "plot", "render", "report", "sample", "sheet", "sheets", "study"})
    if (runGlossy({c, "--help"}).out.find("--merl-dir") != std::string::npos) {
      EXPECT_TRUE(commands.count(c)) << c << " takes --merl-dir";
    }
  for (const char* bad : {"missing", "file", "fifo"})
    for (const auto& [name, args] : commands) {
      SCOPED_TRACE(name + " --merl-dir " + bad);
      std::vector<std::string> with = args;
      with.insert(with.begin() + 1, {"--merl-dir", (tmp / bad).string()});
      expectOneLineError(runGlossy(with, "0,0,1,0,0,1\n"), "--merl-dir " + (tmp / bad).string() + ": ");
    }
  EXPECT_FALSE(std::filesystem::exists(out)) << "refused before any work";
  // $GLOSSY_MERL_DIR set but not a folder: the same, naming the variable.
  for (const char* bad : {"missing", "file", "fifo"}) {
    SCOPED_TRACE(std::string("$GLOSSY_MERL_DIR ") + bad);
    const MerlDirVariable variable(tmp / bad);
    expectOneLineError(runGlossy(commands.at("error")), "$GLOSSY_MERL_DIR " + (tmp / bad).string() + ": ");
  }
}

// A material file finds what sits beside it — its embedded network — by one rule, whatever the working folder:
// run in the material's own folder with a bare file name, in its parent, or with an absolute path, every
// command that reads a material's measured data reads the same network (materialFolder, resolveMeasured).
TEST(MeasuredResolution, AMaterialFindsItsNetworkWhateverTheWorkingFolder) {
  TempDir tmp;
  std::filesystem::create_directories(tmp / "lib");
  for (const char* f : {"alum-bronze.toml", "alum-bronze.nbrdf"}) std::filesystem::copy_file(materialsDir() / f, tmp / "lib" / f);
  // The figures of `glossy error`, past its first line (which names the data by its path from here).
  const auto figures = [](const RunResult& r) { return r.out.substr(std::min(r.out.find('\n'), r.out.size())); };
  std::string expected;
  for (const auto& [cwd, material] : std::vector<std::pair<std::filesystem::path, std::string>>{
           {tmp / "lib", "alum-bronze.toml"}, {tmp.path(), "lib/alum-bronze.toml"}, {tmp / "lib", (tmp / "lib/alum-bronze.toml").string()}}) {
    SCOPED_TRACE(cwd.string() + ": " + material);
    const RunResult error = runGlossyIn(cwd, {"GLOSSY_MERL_DIR"}, {"error", "--material", material});
    ASSERT_EQ(error.status, 0) << error.err;
    EXPECT_NE(error.out.find("NBRDF"), std::string::npos) << error.out;
    if (expected.empty()) expected = figures(error);
    EXPECT_EQ(figures(error), expected);
    const RunResult sheet = runGlossyIn(cwd, {"GLOSSY_MERL_DIR"},
                                        {"sheet", "--material", material, "--width", "8", "--height", "8", "--spp", "1", "--panels",
                                         "measured,cook-torrance:E2", "-o", (tmp / "out/s.exr").string()});
    ASSERT_EQ(sheet.status, 0) << sheet.err;
    EXPECT_EQ((sheet.out + sheet.err).find("no measured"), std::string::npos) << sheet.out << sheet.err;
    EXPECT_EQ((sheet.out + sheet.err).find("no MERL data"), std::string::npos) << sheet.out << sheet.err;
  }
}

}  // namespace glossy::test
