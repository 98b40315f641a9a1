// glossy report of a study's output (renderer/report/study_page.h, report_site.cpp): the study's page with a
// row per model of every sheet, each linking to its sheet's page in the sheets site of its scene and
// lighting; the analysis's files copied and shown; every link inside the site.
#include "renderer/study/study_rows.h"
#include "support/test_support.h"

#include <gtest/gtest.h>

#include <regex>
#include <set>

using namespace glossy;
using namespace glossy::test;

namespace fs = std::filesystem;

namespace {

// A tiny study, rendered and analysed once for the suite.
const fs::path& studyDir() {
  static TempDir tmp;
  static const fs::path dir = [] {
    writeText(tmp / "tiny.toml", R"(materials = ["merl/chrome", "merl/gold-paint"]
[lightings]
sky = { sky = true }
"dim-grey" = { constant = 0.5 }
[settings]
width = 16
height = 16
spp = 8
seed = 3
panels = "measured,microfacet:E2,cook-torrance:E2"
[analysis]
resamples = 100
)");
    const RunResult r = runGlossy({"study", (tmp / "tiny.toml").string(), "-o", (tmp / "out").string()});
    if (r.status != 0) throw std::runtime_error("glossy study failed: " + r.err);
    return tmp / "out";
  }();
  return dir;
}


}  // namespace

TEST(StudyReport, EveryRowLinksToItsSheetsPageAndEveryLinkIsInTheSite) {
  TempDir tmp;
  const fs::path site = tmp / "site";
  const RunResult r = runGlossy({"report", studyDir().string(), "-o", site.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("4 sheets of 2 materials"), std::string::npos) << "each material under two lightings: " << r.err;
  const std::string index = readText(site / "index.html");
  const std::vector<study::StudyRow> rows = study::readStudyRows(studyDir());
  ASSERT_EQ(rows.size(), 2u * 2u * 2u);
  size_t shown = 0;
  for (size_t at = index.find("<tr data-name="); at != std::string::npos; at = index.find("<tr data-name=", at + 1)) ++shown;
  EXPECT_EQ(shown, rows.size()) << "a row of the table per row of the study";
  for (const study::StudyRow& row : rows) {
    const std::string page = "sheets/" + row.scene + "/" + row.lighting + "/materials/" + row.material + "/index.html";
    EXPECT_NE(index.find("href=\"" + page + "\""), std::string::npos) << page;
    EXPECT_TRUE(fs::is_regular_file(site / page)) << page;
  }
  // Each scene and lighting has a sheets site of its own, with its index.
  for (const char* lighting : {"sky", "dim-grey"}) EXPECT_TRUE(fs::is_regular_file(site / "sheets/preview" / lighting / "index.html"));

  // The analysis's files, copied as they are; its figures shown.
  size_t copied = 0;
  for (const auto& e : fs::recursive_directory_iterator(studyDir() / "analysis")) {
    if (!e.is_regular_file()) continue;
    const std::string relative = fs::relative(e.path(), studyDir() / "analysis").generic_string();
    ASSERT_TRUE(fs::is_regular_file(site / "analysis" / relative)) << relative;
    EXPECT_TRUE(readText(site / "analysis" / relative) == readText(e.path())) << relative;
    EXPECT_NE(index.find("\"analysis/" + relative + "\""), std::string::npos) << relative << " is neither shown nor linked";
    if (e.path().extension() == ".svg") {
      EXPECT_NE(index.find("<img src=\"analysis/" + relative + "\""), std::string::npos) << relative;
    }
    ++copied;
  }
  EXPECT_GT(copied, 0u);

  // Every reference of every page stays inside the site and is there.
  for (const auto& e : fs::recursive_directory_iterator(site)) {
    if (e.path().extension() != ".html") continue;
    const std::string html = readText(e.path());
    for (const std::string& ref : htmlReferences(html)) {
      if (ref.starts_with("data:")) continue;
      const fs::path target = (e.path().parent_path() / ref).lexically_normal();
      EXPECT_TRUE(fs::is_regular_file(target)) << e.path() << " refers to " << ref << ", which is not in the site";
      EXPECT_TRUE(target.string().starts_with(site.string())) << ref;
    }
  }

  // Made again over itself: the same files.
  const RunResult again = runGlossy({"report", studyDir().string(), "-o", site.string()});
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(readText(site / "index.html"), index);
}

// The study page renders its summary's markdown (never as raw text, never letting markup through),
// captions each figure by what it shows, and gives the filter every text column's words to match, its count
// naming rows.
TEST(StudyReport, TheSummaryIsRenderedEachFigureCaptionedAndRowsFoundByEveryColumn) {
  TempDir tmp;
  const RunResult r = runGlossy({"report", studyDir().string(), "-o", (tmp / "site").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string index = readText(tmp / "site/index.html");
  EXPECT_NE(index.find("<h3>Study summary</h3>"), std::string::npos) << "the summary's heading, rendered";
  EXPECT_EQ(index.find("# Study summary"), std::string::npos) << "no raw markdown";
  EXPECT_NE(index.find("<code>results.json</code>"), std::string::npos);
  EXPECT_EQ(index.find("```"), std::string::npos);
  // Each figure captioned as the analysis captions it (results.json's figures).
  EXPECT_NE(index.find("<figcaption>The noise-free relative RMSE r* of every model on every material"), std::string::npos) << "error_curves captioned";
  EXPECT_NE(index.find("<figcaption>Mean rank of each model"), std::string::npos);
  // The lighting section: a table per lighting, the agreement across them, the small sample stated.
  EXPECT_NE(index.find("<h4>Lighting</h4>"), std::string::npos);
  for (const char* lighting : {"<h5>dim-grey: 2 materials, 2 sheets</h5>", "<h5>sky: 2 materials, 2 sheets</h5>", "<h5>Across lightings</h5>"})
    EXPECT_NE(index.find(lighting), std::string::npos) << lighting;
  EXPECT_NE(index.find("<th scope=\"col\">median r* [95 %]</th>"), std::string::npos);
  EXPECT_NE(index.find("Friedman test: none (n/a: 2 materials; tests need \xE2\x89\xA5 6)"), std::string::npos);
  EXPECT_NE(index.find("\"analysis/lighting.tex\""), std::string::npos);
  EXPECT_EQ(index.find("<figcaption>error_curves.svg</figcaption>"), std::string::npos);
  EXPECT_NE(index.find("data-noun=\"rows\""), std::string::npos);
  const std::vector<study::StudyRow> rows = study::readStudyRows(studyDir());
  ASSERT_FALSE(rows.empty());
  const study::StudyRow& row = rows.front();
  const std::regex name("<tr data-name=\"([^\"]*)\"");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(index, m, name));
  for (const std::string& word : {row.material, row.database, row.lighting, row.scene, row.fit}) {
    if (!word.empty()) {
      EXPECT_NE(m[1].str().find(word), std::string::npos) << word << " not in the filter's words: " << m[1].str();
    }
  }
}

// A study with a sheet missing is refused, naming it, and nothing is written.
TEST(StudyReport, AnUnfinishedStudyIsRefused) {
  TempDir tmp;
  fs::copy(studyDir(), tmp / "out", fs::copy_options::recursive);
  fs::remove(tmp / "out/sheets/preview/sky/chrome.exr");
  const RunResult r = runGlossy({"report", (tmp / "out").string(), "-o", (tmp / "site").string()});
  expectOneLineError(r, "sheets/preview/sky/chrome.exr");
  EXPECT_FALSE(fs::exists(tmp / "site/index.html"));
}

// With a perceptual folder in the plan, each row carries its material's class from the dataset.
TEST(StudyRows, TheClassComesFromThePerceptualData) {
  GLOSSY_REQUIRE_SHARED("perceptual");
  TempDir tmp;
  fs::copy(studyDir(), tmp / "out", fs::copy_options::recursive);
  std::string plan = readText(tmp / "out/study.json");
  const std::string none = "\"perceptual\": \"\"";
  ASSERT_NE(plan.find(none), std::string::npos) << plan;
  plan.replace(plan.find(none), none.size(), "\"perceptual\": \"" + (sharedDir() / "perceptual").string() + "\"");
  writeText(tmp / "out/study.json", plan);
  for (const study::StudyRow& row : study::readStudyRows(tmp / "out")) EXPECT_EQ(row.materialClass, "Metal") << row.material;
  for (const study::StudyRow& row : study::readStudyRows(studyDir())) EXPECT_EQ(row.materialClass, "") << "no perceptual folder, no class";
}

// A row carries the sheet's stored warnings (glossy:warnings) and, without a verdict, why there is none.
TEST(StudyRows, TheWarningIsTheSheetsStoredWarnings) {
  SheetRecord sheet;
  sheet.verdict = "tie: Microfacet E2, Smooth E2";
  EXPECT_EQ(study::sheetWarning(sheet), "");
  sheet.warnings = {"noise is up to 93 % of a plain figure's square: the intervals may be too narrow", "second"};
  EXPECT_EQ(study::sheetWarning(sheet), sheet.warnings[0] + "; second");
  sheet.verdict = "no verdict: the measured panel is below its noise";
  EXPECT_EQ(study::sheetWarning(sheet), sheet.warnings[0] + "; second; " + sheet.verdict);
  sheet.warnings.clear();
  EXPECT_EQ(study::sheetWarning(sheet), sheet.verdict);
}
