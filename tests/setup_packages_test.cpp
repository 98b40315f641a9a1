// What the set-up scripts install: the main job (scripts/setup, which scripts/run calls) gets the build and
// what glossy runs, never a daemon. On a workstation with systemd, installing Slurm or munge enables and
// starts their services, so those belong to the cluster test's own set-up (scripts/setup-cluster), and the
// test-only packages (Chromium) to scripts/test.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <set>
#include <sstream>
#include <string>

#include "support/test_support.h"

namespace {

std::string commandOutput(const std::string& command) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return out;
  std::array<char, 4096> buffer{};
  size_t n = 0;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) out.append(buffer.data(), n);
  EXPECT_EQ(pclose(pipe), 0) << command;
  return out;
}

std::set<std::string> words(const std::string& text) {
  std::set<std::string> out;
  std::istringstream in(text);
  for (std::string w; in >> w;) out.insert(w);
  return out;
}

std::set<std::string> packagesOf(const std::string& script) {
  return words(commandOutput(glossy::test::shellQuote((glossy::test::sourceDir() / "scripts" / script).string()) +
                             " --packages"));
}

// Packages whose installation runs a daemon: Slurm's and munge's.
const std::set<std::string> kDaemons = {"slurmctld", "slurmd", "slurmdbd", "slurm-client", "munge"};

}  // namespace

TEST(SetupPackages, TheMainJobInstallsNoDaemonAndNoTestTool) {
  const auto setup = packagesOf("setup");
  ASSERT_GT(setup.size(), 10u);
  for (const auto& p : setup) {
    EXPECT_EQ(kDaemons.count(p), 0u) << "scripts/setup installs " << p;
    EXPECT_NE(p, "chromium") << "scripts/setup installs the browser test's chromium";
  }
}

TEST(SetupPackages, NothingTheMainJobInstallsPullsInADaemon) {
  if (std::system("command -v apt-cache >/dev/null 2>&1") != 0) GTEST_SKIP() << "apt-cache is absent (not Debian)";
  const auto setup = packagesOf("setup");
  std::string list;
  for (const auto& p : setup) list += " " + p;
  // What apt-get install --no-install-recommends would bring: the dependency closure without recommends.
  const auto closure = words(commandOutput(
      "apt-cache depends --recurse --no-recommends --no-suggests --no-conflicts --no-breaks --no-replaces "
      "--no-enhances" + list + " 2>/dev/null | grep -v '^ '"));
  if (closure.size() < setup.size()) GTEST_SKIP() << "apt-cache knows no package list here (apt-get update)";
  for (const auto& p : closure) EXPECT_EQ(kDaemons.count(p), 0u) << "scripts/setup's packages pull in " << p;
}

TEST(SetupPackages, TheTestAndClusterSetUpsBringTheRest) {
  const auto test = packagesOf("test");
  EXPECT_EQ(test.count("chromium"), 1u);
  EXPECT_EQ(test.count("texlive-latex-base"), 1u) << "pdflatex, which compiles a study's LaTeX";
  for (const auto& p : test) EXPECT_EQ(kDaemons.count(p), 0u) << "scripts/test installs " << p;
  const auto cluster = packagesOf("setup-cluster");
  for (const auto& p : {"slurmctld", "slurmd", "slurm-client", "munge"}) EXPECT_EQ(cluster.count(p), 1u) << p;
}
