// What rendering a sheet's panels together saves (prints figures, asserts nothing): the default sheet
// (preview scene, built-in sky, 256² per panel, 64 spp, 4 replicates), rendered by renderSheet, beside the
// same panels rendered one by one with render() at the same samples — each panel's 4 replicate passes —
// and at 64 spp in one pass (the sheet before panels shared their paths). Rendering time only (renderSheet
// also computes the object mask, the fits' BRDF errors and the figures: printed beside). Interleaved
// rounds, medians.
#include "bench/timing.h"
#include "materials/merl/merl_table.h"
#include "materials/nbrdf/neural_brdf.h"
#include "renderer/sheet/sheet.h"

#include <CLI/CLI.hpp>

#include <cstdio>

using namespace glossy;
using namespace glossy::bench;

int main(int argc, char** argv) {
  CLI::App app{"sheet_cost: a sheet's panels rendered together against one by one"};
  std::string material = "gold-paint", merlDir = std::string(GLOSSY_SHARED_DIR) + "/merl";
  int rounds = 3, size = 256, spp = 64, threads = 0;
  app.add_option("--material", material, "Material of the library")->capture_default_str();
  app.add_option("--merl-dir", merlDir, "Folder with its MERL table")->capture_default_str();
  app.add_option("--rounds", rounds, "Interleaved rounds (the median is reported)")->capture_default_str();
  app.add_option("--size", size, "Panel width and height")->capture_default_str();
  app.add_option("--spp", spp, "Samples per pixel")->capture_default_str();
  app.add_option("--threads", threads, "Threads (0 = all cores)")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  const std::filesystem::path source(GLOSSY_SOURCE_DIR);
  const SceneDescription description = loadGltf(source / "scenes/preview.gltf");
  const EmbreeScene bvh(description);
  const Environment environment = Environment::makeDefault();
  const Camera& camera = description.cameras.front();
  const SheetScene scene = makeSheetScene(description, bvh, environment, camera);
  const MaterialFile m = loadMaterialFile(source / "materials/library/merl" / (material + ".toml"));
  const auto table = resolveMeasured(m.measured, merlDir, m.path.parent_path());
  if (!table) {
    std::fprintf(stderr, "sheet_cost: no %s in %s\n", m.measured.c_str(), merlDir.c_str());
    return 2;
  }
  const auto measured = std::make_shared<const MerlTable>(
      table->extension() == ".nbrdf" ? NeuralBrdf::load(*table).tabulate() : MerlTable::load(*table));

  SheetSettings settings;
  settings.width = settings.height = size;
  settings.spp = spp;
  settings.threads = threads;
  settings.progress = false;
  std::vector<Brdf> brdfs = {Measured(measured)};
  for (const SheetPanel& p : sheetPanels())
    if (!p.fit.empty()) brdfs.push_back(makeBrdf(*m.find(FitId::parse(p.fit, "sheet_cost"))));

  // One panel alone, as `glossy render` would: its BRDF on the object.
  const auto solo = [&](const Brdf& brdf, int passSpp, int firstSample) {
    RenderSettings r{.width = size, .height = size, .spp = passSpp, .firstSample = firstSample, .maxDepth = settings.maxDepth,
                     .seed = 0, .threads = threads, .progress = false};
    RenderStats stats;
    render(scene.withObject(brdf), camera, r, stats);
  };

  std::vector<double> together, whole, apart, apartOnePass;
  double share = 0.0;
  for (int round = 0; round < rounds; ++round) {
    whole.push_back(seconds([&] {
      const Sheet sheet = renderSheet(scene, m, measured, "", settings);
      share = sheet.objectShare;
      together.push_back(sheet.seconds);
    }));
    const int perReplicate = (spp + kReplicates - 1) / kReplicates;
    apart.push_back(seconds([&] {
      for (const Brdf& b : brdfs)
        for (int j = 0; j < kReplicates; ++j) solo(b, perReplicate, j * perReplicate);
    }));
    apartOnePass.push_back(seconds([&] {
      for (const Brdf& b : brdfs) solo(b, spp, 0);
    }));
    std::printf("round %d: together %.2f s (renderSheet %.2f s), one by one %.2f s (one pass each: %.2f s)\n", round + 1,
                together.back(), whole.back(), apart.back(), apartOnePass.back());
  }
  std::printf("%s, %d² per panel, %d spp, %zu panels, %.1f %% of paths reach the object\n", material.c_str(), size, spp,
              brdfs.size(), 100.0 * share);
  std::printf("median: together %.2f s, one by one %.2f s: ratio %.3f (against one pass each: %.3f); renderSheet with its "
              "mask, BRDF errors and figures: %.2f s\n",
              median(together), median(apart), median(together) / median(apart), median(together) / median(apartOnePass),
              median(whole));
}
