// The option table (renderer/app/option_specs.h) is what every consumer uses: the command line refuses
// each option just beyond its range in the table's words, the docs' table is the table, a render's EXR
// metadata and a sheet's settings line carry the names it gives. Python's keywords: tests/python/test_options.py.
#include "materials/core/text.h"
#include "renderer/app/option_specs.h"
#include "renderer/app/render_job.h"
#include "renderer/app/sheet_job.h"
#include "tests/support/test_support.h"

#include <fstream>
#include <sstream>

namespace glossy::test {

using namespace glossy::app;

TEST(OptionSpecs, TheDocsTableIsTheTable) {
  std::ifstream in(sourceDir() / "docs/rendering.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string docs = text.str(), begin = "<!-- options: begin -->\n", end = "<!-- options: end -->";
  const size_t a = docs.find(begin), b = docs.find(end);
  ASSERT_NE(a, std::string::npos) << "docs/rendering.md has no " << begin;
  ASSERT_NE(b, std::string::npos);
  EXPECT_EQ(docs.substr(a + begin.size(), b - a - begin.size()), optionTable()) << "paste this table into docs/rendering.md";
}

TEST(OptionSpecs, TheCommandLineRefusesJustBeyondEachRangeInTheTablesWords) {
  TempDir tmp;
  const std::string chrome = (materialsDir() / "chrome.toml").string(), exr = (tmp / "x.exr").string();
  for (const OptionSpec* spec : optionSpecs()) {
    const std::string_view of = spec->commands;
    std::vector<std::string> args;
    if (of.starts_with("render")) args = {"render", "-o", exr};
    else if (of.starts_with("sheet")) args = {"sheet", "--material", chrome, "-o", exr};
    else if (of.starts_with("fit")) args = {"fit", "--measured", (tmp / "absent.binary").string()};
    else args = {"sample", "--material", chrome, "--fit", "smooth:E2", "--wo", "0,0,1"};
    if (args.front() == "sample" && spec->name != "n") args.insert(args.end(), {"-n", "1"});
    // Past the top: the bottom goes through the same check (tests/cli_numbers_test.cpp tries both ends).
    for (const double bad : {spec->whole ? spec->hi + 1 : spec->hi * 2 + 1}) {
      const std::string text = spec->whole ? std::to_string((long long)bad) : formatted("%g", bad);
      std::vector<std::string> run = args;
      run.insert(run.end(), {spec->flag(), text});
      SCOPED_TRACE(run.front() + " " + run[run.size() - 2] + " " + text);
      const RunResult r = runGlossy(run);
      EXPECT_EQ(r.status, 2);
      EXPECT_NE(r.err.find(spec->refusal(text)), std::string::npos) << r.err;
    }
  }
  EXPECT_FALSE(std::filesystem::exists(exr));
}

TEST(OptionSpecs, RenderMetadataAndSheetSettingsCarryTheTablesNames) {
  RenderJob job;
  job.settings.width = job.settings.height = 8;
  job.settings.spp = 1;
  job.settings.threads = 2;
  job.settings.progress = false;
  const RenderedImage r = renderImage(job);
  SheetJob sheet;
  const Stage stage(sheet.scene, 1.0);
  const std::string line = sheetSettings(loadMaterialFile(materialsDir() / "chrome.toml"), stage, sheet, "");
  for (const OptionSpec* spec : optionSpecs()) {
    SCOPED_TRACE(std::string(spec->name) + " of " + std::string(spec->commands));
    if (!spec->resumeKey.empty()) {
      EXPECT_NE(line.find("; " + std::string(spec->resumeKey) + "="), std::string::npos) << line;
    }
    if (!spec->attribute.empty() && spec->commands.starts_with("render")) {
      EXPECT_TRUE(std::any_of(r.metadata.begin(), r.metadata.end(), [&](const ImageAttribute& a) { return a.name == spec->attribute; }));
    }
  }
}

}  // namespace glossy::test
