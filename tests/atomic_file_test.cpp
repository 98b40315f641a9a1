// Outputs are written through a temporary renamed into place; a temporary that exists when the process is
// interrupted (SIGINT, SIGTERM, SIGHUP) is removed by the handler, and the process still ends by the signal.
#include "renderer/util/atomic_file.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <csignal>
#include <sys/wait.h>
#include <unistd.h>

namespace glossy::test {

namespace {

std::vector<std::string> temporariesIn(const std::filesystem::path& folder) {
  std::vector<std::string> found;
  for (const auto& e : std::filesystem::directory_iterator(folder))
    if (e.path().filename().string().find(".tmp.") != std::string::npos) found.push_back(e.path().filename().string());
  return found;
}

// Forks a child that starts writing `target` through a PendingTemporary and is then sent `sig`; returns
// the child's wait status.
int interruptedWrite(const std::filesystem::path& target, int sig, bool withHandler) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (withHandler) removeTemporariesOnSignal();
    PendingTemporary tmp(target);
    const char half[] = "half an image";
    if (::write(tmp.fd(), half, sizeof half) < 0) ::_exit(3);
    ::kill(::getpid(), sig);
    ::_exit(4);  // not reached: the signal ends the process
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return status;
}

}  // namespace

TEST(AtomicFile, WritesTheWholeFileAndLeavesNoTemporary) {
  TempDir dir;
  writeFileAtomically(dir / "a.txt", "first");
  writeFileAtomically(dir / "a.txt", "second");
  EXPECT_EQ(readText(dir / "a.txt"), "second");
  EXPECT_TRUE(temporariesIn(dir.path()).empty());
  EXPECT_EQ(std::filesystem::status(dir / "a.txt").permissions() & std::filesystem::perms::others_read,
            std::filesystem::perms::others_read);
}

TEST(AtomicFile, AFailedWriteLeavesNeitherFileNorTemporary) {
  TempDir dir;
  std::filesystem::create_directory(dir / "taken.exr");  // rename over a folder fails
  EXPECT_THROW(writeFileAtomically(dir / "taken.exr", "x"), std::runtime_error);
  EXPECT_TRUE(temporariesIn(dir.path()).empty());
}

TEST(AtomicFile, ATemporaryIsRemovedWhenASignalStopsTheProcess) {
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    SCOPED_TRACE(strsignal(sig));
    TempDir dir;
    const int status = interruptedWrite(dir / "sheet.exr", sig, true);
    ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
    EXPECT_EQ(WTERMSIG(status), sig);  // ended by the signal itself, as without the handler
    EXPECT_TRUE(temporariesIn(dir.path()).empty());
    EXPECT_FALSE(std::filesystem::exists(dir / "sheet.exr"));
  }
}

TEST(AtomicFile, WithoutTheHandlerTheInterruptedTemporaryWouldStay) {
  // The control for the test above: the same interruption leaves the temporary when nothing removes it.
  TempDir dir;
  const int status = interruptedWrite(dir / "sheet.exr", SIGTERM, false);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(temporariesIn(dir.path()).size(), 1u);
}

}  // namespace glossy::test
