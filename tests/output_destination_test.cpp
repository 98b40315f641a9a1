// Where a command writes is checked before it starts any work (renderer/app/destination.h): each bad
// destination exits 2 with one line naming the option or the path. The renders and fits asked for here
// would take minutes, so a check that came after the work would fail these tests by their time limit
// and by the outputs they would leave.
#include "tests/support/test_support.h"

#include <unistd.h>

namespace glossy::test {

namespace {

// Settings that would keep glossy busy for minutes if the destination were not refused first.
std::vector<std::string> slow(std::vector<std::string> args) {
  for (const char* a : {"--width", "512", "--height", "512", "--spp", "100000"}) args.push_back(a);
  return args;
}

const std::string kChrome = (materialsDir() / "chrome.toml").string();

}  // namespace

TEST(CliDestination, RenderAndSheetRefuseBadOutputFilesBeforeRendering) {
  TempDir tmp;
  std::filesystem::create_directories(tmp / "folder.exr");
  writeText(tmp / "file", "");
  for (const std::string command : {"render", "sheet"}) {
    const std::vector<std::string> material =
        command == "render" ? std::vector<std::string>{} : std::vector<std::string>{"--material", kChrome};
    const auto run = [&](const std::string& out) {
      std::vector<std::string> args{command};
      args.insert(args.end(), material.begin(), material.end());
      args.insert(args.end(), {"-o", out});
      return runGlossy(slow(args));
    };
    expectOneLineError(run((tmp / "folder.exr").string()), "folder.exr");
    expectOneLineError(run(""), "-o");
    expectOneLineError(run((tmp / "noext").string()), "noext");
    expectOneLineError(run((tmp / "x.png").string()), "x.png");  // 8 bits would lose the linear values
    expectOneLineError(run((tmp / "x.tiff").string()), "x.tiff");
    expectOneLineError(run((tmp / "file" / "x.exr").string()), "not a folder");
  }
  EXPECT_FALSE(std::filesystem::exists(tmp / "noext"));
  EXPECT_FALSE(std::filesystem::exists(tmp / "x.png"));
  EXPECT_TRUE(std::filesystem::is_empty(tmp / "folder.exr"));
}

TEST(CliDestination, SheetsAndImportRefuseAFileOrEmptyPathAsTheirFolder) {
  TempDir tmp;
  writeText(tmp / "file", "");
  expectOneLineError(runGlossy(slow({"sheets", kChrome, "-o", (tmp / "file").string()})), "file");
  expectOneLineError(runGlossy(slow({"sheets", kChrome, "-o", ""})), "-o");
  expectOneLineError(runGlossy({"import", (sharedDir() / "seed/supplement.txt").string(), "-o", (tmp / "file").string()}),
                     "file");
  EXPECT_EQ(readText(tmp / "file"), "");
}

TEST(CliDestination, FitRefusesAMissingFolderAndAWrongExtensionBeforeFitting) {
  GLOSSY_REQUIRE_SHARED("merl/alum-bronze.binary.xz");
  TempDir tmp;
  const std::string table = (sharedDir() / "merl/alum-bronze.binary.xz").string();
  const auto fit = [&](const std::string& out) {
    return runGlossy({"fit", "--measured", table, "--model", "cook-torrance", "--metric", "E2", "-o", out});
  };
  expectOneLineError(fit((tmp / "missing-dir" / "x.toml").string()), "missing-dir");
  expectOneLineError(fit((tmp / "x.exr").string()), "x.exr");
  expectOneLineError(fit(tmp.path().string()), tmp.path().string());
  EXPECT_FALSE(std::filesystem::exists(tmp / "missing-dir"));
  writeText(tmp / "file", "");
  expectOneLineError(runGlossy({"fit", "--measured-dir", (sharedDir() / "merl").string(), "--out-dir", (tmp / "file").string()}),
                     "--out-dir");
}

// A suite of its own: it skips as root, and CTest reports a suite that skipped a case as skipped
// (tests/batches/), which would hide the other destination checks' passes.
TEST(ReadOnlyDestination, AReadOnlyFolderIsRefusedBeforeRendering) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only folders";
  TempDir tmp;
  std::filesystem::create_directories(tmp / "ro");
  std::filesystem::permissions(tmp / "ro", std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
  expectOneLineError(runGlossy(slow({"render", "-o", (tmp / "ro" / "x.exr").string()})), "not writable");
  expectOneLineError(runGlossy(slow({"sheets", kChrome, "-o", (tmp / "ro" / "out").string()})), "not writable");
  std::filesystem::permissions(tmp / "ro", std::filesystem::perms::owner_all);
}

}  // namespace glossy::test
