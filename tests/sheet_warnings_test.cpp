// A sheet's warnings and its noise-floor row: no model is named closest while a warning stands, and both
// reach every reader of the sheet (the table, the EXR and the report's record of it, the PNG's strip).
#include "renderer/report/site_layout.h"
#include "renderer/sheet/sheet.h"
#include "renderer/sheet/sheet_record.h"
#include "tests/support/test_support.h"

namespace glossy::test {

namespace {

PanelFigures figures(double relativeRmse, double noisy) {
  PanelFigures f;
  f.compared = f.available = f.hasCi = true;
  f.relativeRmse = relativeRmse;
  f.noisyRelativeRmse = noisy;
  return f;
}

}  // namespace

TEST(SheetWarnings, NoiseSwampingAFigureWarnsAndWithholdsTheClosestModel) {
  // Noise 1 − 0.05² / 0.2² = 94 % of a plain figure's square: warned; 1 − 0.15² / 0.2² = 44 %: not.
  const std::vector<std::string> warnings = figureWarnings({figures(0.15, 0.2), figures(0.05, 0.2)});
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings.front().find("noise is up to 94 %"), std::string::npos) << warnings.front();
  EXPECT_TRUE(figureWarnings({figures(0.15, 0.2)}).empty());

  const Verdict closest{{1}, "closest: every other model's squared error is larger by more than 1.96 standard errors"};
  const Verdict held = verdictUnderWarnings(closest, warnings);
  EXPECT_TRUE(held.models.empty());
  EXPECT_TRUE(held.why.starts_with("no verdict: the intervals may be too narrow")) << held.why;
  EXPECT_EQ(verdictUnderWarnings(closest, {}).models, closest.models) << "no warning: the verdict stands";
  const Verdict tie{{1, 0}, "tie: …"};
  EXPECT_EQ(verdictUnderWarnings(tie, warnings).models, tie.models) << "a tie names no model closest";
}

TEST(SheetWarnings, TheWarningAndTheNoiseFloorReachTheExrTheTableAndTheReport) {
  GLOSSY_REQUIRE_SHARED("merl/alum-bronze.binary.xz");
  TempDir tmp;
  // 32² at 8 spp: noise swamps the figures, so the sheet warns.
  const RunResult r = runGlossy({"sheet", "--material", (materialsDir() / "alum-bronze.toml").string(), "--merl-dir",
                                 (sharedDir() / "merl").string(), "--width", "32", "--height", "32", "--spp", "8", "--seed", "5",
                                 "--threads", "2", "-o", (tmp / "alum-bronze.exr").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const SheetRecord s = readSheetRecord(tmp / "alum-bronze.exr");
  ASSERT_FALSE(s.warnings.empty()) << r.out;
  EXPECT_NE(r.out.find("  warning: " + s.warnings.front()), std::string::npos) << r.out;
  EXPECT_FALSE(s.verdict.starts_with("closest: ")) << s.verdict;
  EXPECT_FALSE(s.closestLayers().size() == 1 && !s.isTie()) << s.verdict;

  // The noise-floor row: in the table, and its figures in the EXR: an r* interval from 0 (the panel is the
  // measured one) and a luminance ratio whose interval holds 1.
  EXPECT_NE(r.out.find("  noise floor "), std::string::npos) << r.out;
  ASSERT_TRUE(s.noiseFloor);
  const ImageFigures& f = *s.noiseFloor;
  ASSERT_TRUE(f.relativeRmse.value && f.relativeRmse.lo && f.relativeRmse.hi && f.luminanceRatio.lo && f.flip.value);
  EXPECT_EQ(*f.relativeRmse.lo, 0.0);
  EXPECT_GT(*f.relativeRmse.hi, 0.0);
  EXPECT_LE(*f.luminanceRatio.lo, 1.0);
  EXPECT_GE(*f.luminanceRatio.hi, 1.0);
  EXPECT_GT(*f.flip.value, 0.0);
  EXPECT_GT(*f.relativeRmseNoisy, 0.0);
  EXPECT_EQ(readImageAttribute(tmp / "alum-bronze.exr", "glossy:noiseFloor.seed"), std::to_string(noiseFloorSeed(5)));
  // The report: the warning under the verdict on the index and on the material's page, the floor's row.
  const RunResult site = runGlossy({"report", tmp.path().string(), "-o", (tmp / "site").string()});
  ASSERT_EQ(site.status, 0) << site.err;
  const std::string page = readText(tmp / "site" / report::layout::materialPage("alum-bronze"));
  EXPECT_NE(page.find("<p class=\"warning\">Warning: noise is up to"), std::string::npos);
  EXPECT_NE(page.find("<tr class=\"noise-floor\">"), std::string::npos);
  EXPECT_NE(readText(tmp / "site" / report::layout::kIndex).find("<span class=\"warning\">warning: noise is up to"), std::string::npos);
  // The PNG: the maps' row, then the strip with the floor and the warnings.
  EXPECT_EQ(s.pngHeight, sheetPngSize(32, 32, 7).heightWithMaps);
  EXPECT_GT(sheetPngSize(32, 32, 7).heightWithMaps, sheetPngSize(32, 32, 7).height + 32);
}

TEST(SheetWarnings, TheNoiseFloorRenderIsAnotherSeedsMeasuredPanel) {
  EXPECT_NE(noiseFloorSeed(0), 0u);
  for (uint32_t seed : {0u, 1u, 2u, 1000u, 0xFFFFFFFFu}) EXPECT_NE(noiseFloorSeed(seed), seed);
  EXPECT_NE(noiseFloorSeed(1), noiseFloorSeed(2));
}

}  // namespace glossy::test
