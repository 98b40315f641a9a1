// One writer per destination (renderer/util/output_lock.h): a second lock on a destination is refused
// naming it; the lock file, and folders made for it, are gone once released; a file of the lock's name that
// glossy did not make is left alone; and two glossy runs to one -o never both write it.
#include "renderer/util/output_lock.h"
#include "renderer/image/exr_image.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <thread>

namespace glossy::test {

TEST(OutputLock, ASecondWriterIsRefusedNamingTheOptionAndTheDestination) {
  TempDir dir;
  const std::filesystem::path out = dir / "a.exr";
  {
    const OutputLock first(out, "-o");
    EXPECT_TRUE(std::filesystem::exists(dir / ".a.exr.lock"));
    const std::string e = expectInputError([&] { OutputLock second(out, "-o"); });
    EXPECT_EQ(e, "-o: " + out.string() + " is being written by another glossy process");
    EXPECT_THROW(OutputLock(out, "-o"), OutputBusy);
    EXPECT_NO_THROW(OutputLock(dir / "b.exr", "-o")) << "another destination has its own lock";
  }
  // Released: the lock file is gone, and the destination can be locked again.
  EXPECT_FALSE(std::filesystem::exists(dir / ".a.exr.lock"));
  EXPECT_FALSE(std::filesystem::exists(dir / ".b.exr.lock"));
  EXPECT_NO_THROW(OutputLock(out, "-o"));
}

TEST(OutputLock, FoldersMadeForTheLockGoWhenNothingWasWrittenInThem) {
  TempDir dir;
  { const OutputLock lock(dir / "new/deeper/a.exr", "-o"); EXPECT_TRUE(std::filesystem::is_directory(dir / "new/deeper")); }
  EXPECT_FALSE(std::filesystem::exists(dir / "new")) << "a failed command leaves no empty folders behind";
  {
    const OutputLock lock(dir / "kept/a.exr", "-o");
    writeText(dir / "kept/a.exr", "the output");
  }
  EXPECT_EQ(readText(dir / "kept/a.exr"), "the output");
  EXPECT_FALSE(std::filesystem::exists(dir / "kept/.a.exr.lock"));
}

TEST(OutputLock, AFileOfTheLocksNameIsRemovedOnlyIfGlossyMadeIt) {
  TempDir dir;
  writeText(dir / ".mine.exr.lock", "a user's notes\n");
  { const OutputLock lock(dir / "mine.exr", "-o"); }
  EXPECT_EQ(readText(dir / ".mine.exr.lock"), "a user's notes\n");
  // One a killed run left (glossy's marker in it) is reused, then removed.
  writeText(dir / ".left.exr.lock", "glossy output lock\n");
  { const OutputLock lock(dir / "left.exr", "-o"); }
  EXPECT_FALSE(std::filesystem::exists(dir / ".left.exr.lock"));
  // A symlink in the lock's place does not lead it elsewhere.
  std::filesystem::create_symlink(dir / "elsewhere", dir / ".link.exr.lock");
  EXPECT_NE(expectInputError([&] { OutputLock lock(dir / "link.exr", "-o"); }).find("-o: "), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "elsewhere"));
}

// Another glossy process holds the lock (as flock sees it): render, sheet and sheets refuse or skip it.
TEST(CliOutputLock, RenderAndSheetRefuseADestinationAnotherRunIsWriting) {
  TempDir dir;
  const int fd = ::open((dir / ".busy.exr.lock").c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const std::string out = (dir / "busy.exr").string();
  RunResult r = runGlossy({"render", "--width", "8", "--height", "8", "--spp", "1", "-o", out});
  expectOneLineError(r, out + " is being written by another glossy process");
  r = runGlossy({"sheet", "--material", (materialsDir() / "chrome.toml").string(), "--width", "8", "--height", "8", "--spp", "1",
                 "-o", out});
  expectOneLineError(r, out + " is being written by another glossy process");
  EXPECT_FALSE(std::filesystem::exists(out));
  ::close(fd);
  std::filesystem::remove(dir / ".busy.exr.lock");
  r = runGlossy({"render", "--width", "8", "--height", "8", "--spp", "1", "-o", out});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir / ".busy.exr.lock")) << "no lock file is left behind";
}

// Two `glossy sheet` runs to one -o, the second started while the first renders: the second is refused,
// and the EXR and PNG are both the first's.
TEST(CliOutputLock, TwoSheetRunsRacingOnOneOutput) {
  TempDir dir;
  const std::string out = (dir / "race.exr").string();
  const auto args = [&](const char* seed, const char* spp) {
    std::string cmd = "env -u SLURM_ARRAY_TASK_ID ";
    cmd += shellQuote(GLOSSY_EXE);
    for (const std::string& a : {std::string("sheet"), std::string("--material"), (materialsDir() / "chrome.toml").string(),
                                 std::string("--width"), std::string("32"), std::string("--height"), std::string("32"),
                                 std::string("--spp"), std::string(spp), std::string("--seed"), std::string(seed),
                                 std::string("-o"), out})
      cmd.append(" ").append(shellQuote(a));
    return cmd;
  };
  // The first in the background, long enough to be caught rendering; the second once the lock is there.
  const std::string first = args("1", "256") + " >/dev/null 2>" + shellQuote((dir / "first.err").string()) + "; echo $? >" +
                            shellQuote((dir / "first.status").string());
  ASSERT_EQ(std::system(("(" + first + ") &").c_str()), 0);
  const auto start = std::chrono::steady_clock::now();
  while (!std::filesystem::exists(dir / ".race.exr.lock") && std::chrono::steady_clock::now() - start < std::chrono::seconds(20))
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  const RunResult second = runGlossy({"sheet", "--material", (materialsDir() / "chrome.toml").string(), "--width", "32", "--height",
                                      "32", "--spp", "4", "--seed", "2", "-o", out});
  while (!std::filesystem::exists(dir / "first.status") && std::chrono::steady_clock::now() - start < std::chrono::seconds(300))
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_TRUE(std::filesystem::exists(dir / "first.status"));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  EXPECT_EQ(readText(dir / "first.status"), "0\n") << readText(dir / "first.err");
  expectOneLineError(second, out + " is being written by another glossy process");
  EXPECT_NE(readImageAttribute(out, "glossy:settings").find("seed=1;"), std::string::npos);
  EXPECT_EQ(readImageAttribute(out, "glossy:spp"), "256");
  EXPECT_FALSE(std::filesystem::exists(dir / ".race.exr.lock"));
}

// Every command that writes a destination takes its lock: plot and report folders, merge's outputs and a
// parameter file that fit reads and rewrites (two fits into one file must both land, not one lose the other).
TEST(CliOutputLock, PlotReportMergeAndFitRefuseADestinationAnotherRunIsWriting) {
  TempDir dir;
  const auto hold = [&](const std::string& name) {
    const int fd = ::open((dir / ("." + name + ".lock")).c_str(), O_RDWR | O_CREAT, 0644);
    EXPECT_GE(fd, 0);
    EXPECT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
    return fd;
  };
  const std::string chrome = (materialsDir() / "chrome.toml").string();
  const std::string busy = " is being written by another glossy process";
  std::vector<int> held;
  held.push_back(hold("plots"));
  expectOneLineError(runGlossy({"plot", "--material", chrome, "--figures", "albedo", "-o", (dir / "plots").string()}),
                     (dir / "plots").string() + busy);
  std::filesystem::create_directory(dir / "sheets");
  held.push_back(hold("site"));
  expectOneLineError(runGlossy({"report", (dir / "sheets").string(), "-o", (dir / "site").string()}), (dir / "site").string() + busy);
  held.push_back(hold("errors.csv"));
  expectOneLineError(runGlossy({"merge", "sheets", (dir / "sheets").string(), "--csv", (dir / "errors.csv").string()}),
                     (dir / "errors.csv").string() + busy);
  held.push_back(hold("library"));
  expectOneLineError(runGlossy({"merge", "fits", (dir / "sheets").string(), "-o", (dir / "library").string()}),
                     (dir / "library").string() + busy);
  held.push_back(hold("fit.toml"));
  const RunResult fit = runGlossy({"fit", "--measured", (materialsDir() / "chrome.nbrdf").string(), "--model", "microfacet",
                                   "--metric", "E2", "--starts", "1", "--max-iterations", "2", "-o", (dir / "fit.toml").string()});
  expectOneLineError(fit, (dir / "fit.toml").string() + busy);
  EXPECT_FALSE(std::filesystem::exists(dir / "fit.toml"));
  EXPECT_FALSE(std::filesystem::exists(dir / "plots"));
  EXPECT_FALSE(std::filesystem::exists(dir / "site"));
  for (int fd : held) ::close(fd);
}

}  // namespace glossy::test
