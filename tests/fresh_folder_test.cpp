// A folder written whole (renderer/util/fresh_folder.h): what the target holds is the last finished run's
// files and nothing else — never an earlier run's file beside them, never half of a run that failed.
#include "renderer/util/fresh_folder.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <set>

namespace glossy::test {

namespace fs = std::filesystem;

namespace {

std::set<std::string> names(const fs::path& folder) {
  std::set<std::string> out;
  for (const auto& e : fs::directory_iterator(folder)) out.insert(e.path().filename().string());
  return out;
}

}  // namespace

TEST(FreshFolder, AFolderIsReplacedWholeOrNotAtAll) {
  TempDir tmp;
  const fs::path target = tmp / "analysis";
  {
    FreshFolder fresh(target);  // no target yet: renamed into place
    writeText(fresh.path() / "a.svg", "1");
    writeText(fresh.path() / "perceptual.svg", "1");
    fresh.replaceTarget();
  }
  EXPECT_EQ(names(target), (std::set<std::string>{"a.svg", "perceptual.svg"}));
  {
    FreshFolder fresh(target);  // a run that fails half-way: the target stays the earlier run's
    writeText(fresh.path() / "a.svg", "half");
  }
  EXPECT_EQ(names(target), (std::set<std::string>{"a.svg", "perceptual.svg"}));
  EXPECT_EQ(readText(target / "a.svg"), "1");
  {
    FreshFolder fresh(target);  // a run writing fewer files: none of the earlier run's left
    writeText(fresh.path() / "a.svg", "2");
    fresh.replaceTarget();
  }
  EXPECT_EQ(names(target), (std::set<std::string>{"a.svg"}));
  EXPECT_EQ(readText(target / "a.svg"), "2");
  EXPECT_EQ(names(tmp.path()), (std::set<std::string>{"analysis"})) << "no fresh or old folder left beside it";

  // A killed run's fresh folder (named as glossy names them) is cleared by the next; a user's look-alike is not.
  fs::create_directories(tmp / ".analysis.tmp.glossy-abc123");
  fs::create_directories(tmp / ".analysis.tmp.glossy-mine");
  { FreshFolder fresh(target); }
  EXPECT_EQ(names(tmp.path()), (std::set<std::string>{"analysis", ".analysis.tmp.glossy-mine"}));
}

}  // namespace glossy::test
