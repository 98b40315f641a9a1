// The sheet's error figures mean what they say: over 100 seeds of a small sheet (64², the default 64 spp),
// each model's 95 % interval of the noise-free relative RMSE (and of the luminance ratio) contains the
// converged value — the same figure from a 4096-spp sheet — in at least 90 % of seeds, and at most 5 % of
// seeds name a model the converged sheet does not rank first. About 2 minutes on 2 cores.
//
// At 16 spp, where the noise is 2.5 times the error it hides, two of the six models' intervals cover only
// 87–89 % (docs/sheets.md says why, and the sheet's table warns there).
#include "renderer/sheet/sheet.h"
#include "tests/support/test_support.h"

namespace glossy::test {

namespace {

constexpr int kSize = 64, kSpp = 64, kSeeds = 100, kConvergedSpp = 4096;

struct Stage {
  SceneDescription description = loadGltf(sourceDir() / "scenes/preview.gltf");
  EmbreeScene bvh{description};
  Environment environment = Environment::makeDefault();
  SheetScene scene = makeSheetScene(description, bvh, environment, description.cameras.front());
};

Sheet renderAt(const Stage& stage, const MaterialFile& m, std::shared_ptr<const MerlTable> table, int spp, uint32_t seed) {
  SheetSettings s;
  s.width = s.height = kSize;
  s.spp = spp;
  s.seed = seed;
  s.progress = false;
  return renderSheet(stage.scene, m, std::move(table), "", s);
}

}  // namespace

TEST(SheetFigures, IntervalsCoverTheConvergedValues) {
  GLOSSY_REQUIRE_SHARED("merl/gold-paint.binary.xz");
  const Stage stage;
  const MaterialFile m = loadMaterialFile(materialsDir() / "gold-paint.toml");
  const auto table = std::make_shared<const MerlTable>(MerlTable::load(sharedDir() / "merl/gold-paint.binary"));
  const Sheet converged = renderAt(stage, m, table, kConvergedSpp, 1000);
  ASSERT_EQ(converged.verdict.models.size(), 1u) << "the converged sheet must rank one model first: " << verdictText(converged);
  const size_t best = converged.verdict.models.front();

  std::vector<int> rmseCovered(converged.panels.size()), ratioCovered(converged.panels.size());
  int named = 0, wrong = 0;
  for (uint32_t seed = 1; seed <= kSeeds; ++seed) {
    const Sheet sheet = renderAt(stage, m, table, kSpp, seed);
    for (size_t k = 0; k < sheet.panels.size(); ++k) {
      const PanelFigures& f = sheet.panels[k].figures;
      const PanelFigures& c = converged.panels[k].figures;
      if (!c.hasCi) continue;
      ASSERT_TRUE(f.hasCi) << sheet.panels[k].panel.label;
      rmseCovered[k] += f.relativeRmseCi.lo <= c.relativeRmse && c.relativeRmse <= f.relativeRmseCi.hi;
      ratioCovered[k] += f.luminanceRatioCi.lo <= c.luminanceRatio && c.luminanceRatio <= f.luminanceRatioCi.hi;
    }
    if (sheet.verdict.models.size() == 1) {
      ++named;
      wrong += sheet.verdict.models.front() != best;
    }
  }
  for (size_t k = 0; k < converged.panels.size(); ++k) {
    if (!converged.panels[k].figures.hasCi) continue;
    const std::string label = converged.panels[k].panel.label;
    RecordProperty(converged.panels[k].panel.layer + "_rmseCoverage", rmseCovered[k]);
    RecordProperty(converged.panels[k].panel.layer + "_ratioCoverage", ratioCovered[k]);
    EXPECT_GE(rmseCovered[k], kSeeds * 9 / 10) << label << ": relative RMSE " << converged.panels[k].figures.relativeRmse;
    EXPECT_GE(ratioCovered[k], kSeeds * 9 / 10) << label << ": luminance ratio " << converged.panels[k].figures.luminanceRatio;
  }
  RecordProperty("named", named);
  RecordProperty("wrong", wrong);
  EXPECT_LE(wrong, kSeeds / 20) << "of " << named << " verdicts naming one model";
}

}  // namespace glossy::test
