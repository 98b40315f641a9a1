// Numbers on the command line: every floating-point option of every subcommand refuses NaN, ±Inf and
// values out of its range as bad input (exit 2, one short line naming the option), before any work;
// --threads and image sizes have limits that are checked up front; --shard takes exactly i/N.
#include "renderer/app/image_memory.h"
#include "tests/support/test_support.h"

#include <unistd.h>

namespace glossy::test {

namespace {

struct Case {
  std::vector<std::string> command;  // the subcommand and what it needs besides the option
  std::string option;
  std::vector<std::string> bad;
};

std::vector<Case> cases(const TempDir& tmp) {
  const std::string chrome = (materialsDir() / "chrome.toml").string();
  const std::string exr = (tmp / "x.exr").string(), out = (tmp / "out").string();
  const std::vector<std::string> render = {"render", "--width", "8", "--height", "8", "--spp", "1", "-o", exr};
  const std::vector<std::string> sheet = {"sheet", "--material", chrome, "--width", "8", "--height", "8", "--spp", "1", "-o", exr};
  const std::vector<std::string> sheets = {"sheets", chrome, "--width", "8", "--height", "8", "--spp", "1", "-o", out};
  const std::vector<std::string> sample = {"sample", "--material", chrome, "--fit", "smooth:E2", "--wo", "0,0,1"};
  const std::vector<std::string> fit = {"fit", "--measured", (tmp / "absent.binary").string(), "--model", "cook-torrance"};
  const std::vector<std::string> nonFinite = {"nan", "NaN", "inf", "-inf", "1e400"};
  auto with = [](std::vector<std::string> a, std::vector<std::string> b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  std::vector<Case> all;
  // Every value goes to render; sheet and sheets declare the same options with the same checks, so each of
  // theirs gets a non-finite value and an out-of-range one: every glossy process costs its start-up.
  all.push_back({render, "--env-rotate", with(nonFinite, {"1e308", "361", "x"})});
  all.push_back({render, "--env-constant", with(nonFinite, {"1e308", "-1", "1,nan,1", "1,1,1e13"})});
  all.push_back({render, "--threads", with(nonFinite, {"-1", "1e8", "100000000", "4097", "2.5", "1e308"})});
  all.push_back({render, "--width", with(nonFinite, {"0", "-1", "1e308", "99999999999999999999"})});
  all.push_back({render, "--spp", with(nonFinite, {"0", "-1", "1e308"})});
  for (const auto& c : {sheet, sheets}) {
    all.push_back({c, "--env-rotate", {"nan", "361"}});
    all.push_back({c, "--env-constant", {"inf", "1,nan,1"}});
    all.push_back({c, "--threads", {"-inf", "4097"}});
    all.push_back({c, "--width", {"1e400", "0"}});
    all.push_back({c, "--spp", {"NaN", "-1"}});
  }
  all.push_back({sheet, "--time", with(nonFinite, {"0", "-1", "1e308", "1e7"})});
  all.push_back({sheet, "--target-error", with(nonFinite, {"0", "-0.1", "1e308", "11"})});
  all.push_back({sheet, "--exposure", with(nonFinite, {"1e308", "65", "-65"})});
  all.push_back({sheets, "--time", {"nan", "1e7"}});
  all.push_back({sheets, "--target-error", {"-inf", "11"}});
  all.push_back({sheets, "--exposure", {"1e400", "-65"}});
  all.push_back({sample, "-n", with(nonFinite, {"-1", "1e300", "2000000000"})});
  all.push_back({fit, "--threads", with(nonFinite, {"4097", "-1", "1e8"})});
  // A study's numbers are in its file (StudyCli); its command line has --threads.
  const std::vector<std::string> study = {"study", (sourceDir() / "scenes/studies/tiny.toml").string(), "-o", out};
  all.push_back({study, "--threads", {"nan", "4097"}});
  all.push_back({fit, "--starts", with(nonFinite, {"0", "1e308"})});
  all.push_back({fit, "--max-iterations", with(nonFinite, {"0", "1e308"})});
  return all;
}

}  // namespace

TEST(CliNumbers, NonFiniteAndOutOfRangeOptionsAreOneShortLineNamingTheOption) {
  TempDir tmp;
  for (const Case& c : cases(tmp))
    for (const std::string& bad : c.bad) {
      std::vector<std::string> args = c.command;
      args.push_back(c.option);
      args.push_back(bad);
      SCOPED_TRACE(c.command.front() + " " + c.option + " " + bad);
      const RunResult r = runGlossy(args);
      expectOneLineError(r, c.option);
      // A range's ends in full would be 309 digits (std::to_string of a double's maximum).
      EXPECT_LT(r.err.size(), 240u) << r.err;
      EXPECT_EQ(r.err.find("17976931348623157"), std::string::npos) << r.err;
    }
  EXPECT_FALSE(std::filesystem::exists(tmp / "x.exr"));
  EXPECT_FALSE(std::filesystem::exists(tmp / "out"));
}

TEST(CliNumbers, ValuesAtTheEndsOfTheRangesAreAccepted) {
  TempDir tmp;
  const std::string exr = (tmp / "x.exr").string();
  const RunResult r = runGlossy({"render", "--width", "8", "--height", "8", "--spp", "1", "--threads", "1", "--env-rotate",
                                 "-360", "--env-constant", "1e12", "-o", exr});
  EXPECT_EQ(r.status, 0) << r.err;
  const RunResult s = runGlossy({"sheet", "--material", (materialsDir() / "chrome.toml").string(), "--width", "8", "--height",
                                 "8", "--spp", "1", "--exposure", "64", "--env-rotate", "360", "-o", exr});
  EXPECT_EQ(s.status, 0) << s.err;
}

TEST(CliNumbers, ShardMustBeExactlyIOverN) {
  TempDir tmp;
  for (const char* bad : {"0/3/4", "1/0", "3/3", "-1/3", "a/b", "0/3x", "0", "0/"})
    expectOneLineError(runGlossy({"sheets", "--shard", bad, "--spp", "1", "-o", (tmp / "out").string()}), "--shard");
  EXPECT_FALSE(std::filesystem::exists(tmp / "out"));
}

// Sizes whose buffers exceed the machine's memory are refused before anything is loaded, naming the size,
// instead of std::bad_alloc minutes later.
TEST(CliNumbers, ImagesLargerThanMemoryAreRefusedUpFront) {
  TempDir tmp;
  const double memory = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE));
  // Seven 16384² panels need about 600 GB.
  if (memory >= 16384.0 * 16384.0 * 7 * app::kSheetBytesPerPanelPixel) GTEST_SKIP() << "this machine has the memory for the largest sheet";
  for (const char* command : {"sheet", "sheets"}) {
    std::vector<std::string> args = {command, "--width", "16384", "--height", "16384", "--spp", "1"};
    if (std::string(command) == "sheet") args.insert(args.end(), {"--material", (materialsDir() / "chrome.toml").string()});
    args.insert(args.end(), {"-o", (tmp / "out" / "x.exr").string()});
    const RunResult r = runGlossy(args);
    expectOneLineError(r, "--width 16384 --height 16384");
    EXPECT_NE(r.err.find("7 panels"), std::string::npos) << r.err;
  }
  if (memory < 32768.0 * 32768.0 * 64) {
    const RunResult r = runGlossy({"render", "--width", "32768", "--height", "32768", "-o", (tmp / "x.exr").string()});
    expectOneLineError(r, "--width 32768 --height 32768");
  }
  EXPECT_FALSE(std::filesystem::exists(tmp / "out"));
}

}  // namespace glossy::test
