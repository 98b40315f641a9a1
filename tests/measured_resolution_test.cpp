// One rule finds measured data in every command (resolveMeasured, docs/measured.md): a --measured name is
// looked for under --merl-dir, then $GLOSSY_MERL_DIR, then the working folder — eval and sample as render
// (sheet's and fit's are tested with them, in sheet_cli_test and fit_cli_test).
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <cstdlib>

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
