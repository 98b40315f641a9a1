#include "tests/support/library_sheets.h"

#include "renderer/image/exr_image.h"
#include "renderer/sheet/sheet.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace glossy::test {

namespace {

// The label every network of a database folder carries (scripts/nbrdf_from_h5.py).
const std::map<std::string, std::string> kLabels = {{"merl", "MERL (NBRDF reconstruction)"},
                                                    {"rgl-epfl", "RGL-EPFL (NBRDF reconstruction)"},
                                                    {"nielsen2015", "Nielsen 2015 (NBRDF reconstruction)"}};

}  // namespace

std::vector<std::string> libraryMaterials() {
  std::vector<std::string> out;
  for (const auto& [database, label] : kLabels)
    for (const auto& e : std::filesystem::directory_iterator(libraryDir() / database))
      if (e.path().extension() == ".toml") out.push_back(database + "/" + e.path().stem().string());
  std::sort(out.begin(), out.end());
  return out;
}

void expectCompleteSheets(const std::vector<std::string>& materials) {
  TempDir tmp;
  std::vector<std::string> args = {"sheets", "--width", "32", "--height", "32", "--spp", "16", "-o", (tmp / "out").string()};
  for (const std::string& m : materials) args.push_back((libraryDir() / (m + ".toml")).string());
  // The networks in the repository, not a MERL folder that happens to be set.
  const RunResult r = runGlossyIn(tmp.path(), {"GLOSSY_MERL_DIR"}, args);
  ASSERT_EQ(r.status, 0) << r.err;
  for (const std::string& m : materials) {
    SCOPED_TRACE(m);
    const std::string database = m.substr(0, m.find('/')), name = m.substr(m.find('/') + 1);
    const std::filesystem::path exr = tmp / "out" / (name + ".exr");
    ASSERT_TRUE(std::filesystem::exists(exr));
    EXPECT_TRUE(std::filesystem::exists(tmp / "out" / (name + ".png")));
    EXPECT_EQ(readImageAttribute(exr, "glossy:measured").rfind(kLabels.at(database) + " ", 0), 0u)
        << readImageAttribute(exr, "glossy:measured");
    for (const SheetPanel& p : sheetPanels()) {
      EXPECT_EQ(readImageAttribute(exr, "glossy:panel." + p.layer + ".empty"), "0") << p.label;
      if (!p.fit.empty()) {
        EXPECT_FALSE(readImageAttribute(exr, "glossy:error." + p.layer + ".relativeRmseNoisy").empty()) << p.label;
      }
    }
    const std::string verdict = readImageAttribute(exr, "glossy:verdict");
    EXPECT_FALSE(verdict.empty());
    // A closest model or a tie; no verdict only while a stored warning stands (glossy:warnings).
    if (verdict.rfind("no verdict", 0) == 0) {
      EXPECT_FALSE(readImageAttribute(exr, "glossy:warnings").empty()) << verdict;
      EXPECT_NE(verdict.find("the intervals may be too narrow"), std::string::npos) << verdict;
    }
  }
}

}  // namespace glossy::test
