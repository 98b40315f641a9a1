// A study file as `glossy study` loads it (renderer/app/study_file.h): read from a path, its globs matched
// over a material library, its paths resolved against its folder and checked. Then used as the command
// uses it before any sheet renders: its plan written as OUT/study.json and read back (a plan glossy wrote
// must read back as the same plan), each material loaded and costed, the sheets' memory checked, each
// sheet's path and scene options made.
//
// The library is a slice of the repository's (materials/library), copied once per process into its
// folder: a glob over the whole library loads all its 159 files, a few hundred milliseconds under the
// sanitizers, which would be nearly all of the fuzzer's time; a few files of each database reach the same
// code. Beside them, a fourth database folder holding a second copy of one file (two files naming one material),
// and the files a study file points at by relative path: a perceptual folder (slices of the dataset's
// tables), a map and two scenes, so that seeds naming them are accepted.
#include "materials/core/input_error.h"
#include "materials/params/material_file.h"
#include "renderer/app/image_memory.h"
#include "renderer/app/study_file.h"
#include "renderer/study/study_plan.h"
#include "renderer/util/data_dir.h"
#include "tests/fuzz/fuzz_entries.h"
#include "tests/fuzz/fuzz_temp_dir.h"

#include <fstream>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace glossy::fuzz {

namespace {

namespace fs = std::filesystem;

Bytes bytesOf(std::string_view text) { return {reinterpret_cast<const uint8_t*>(text.data()), text.size()}; }

std::string fileText(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string text{std::istreambuf_iterator<char>(in), {}};
  // Not InputError: the repository's library missing is the harness's failure, never the input's.
  if (text.empty()) throw std::runtime_error("fuzz harness: cannot read " + file.string());
  return text;
}

// The study file's surroundings, made once for the process (TempFile names are relative to its folder).
const std::vector<std::unique_ptr<TempFile>>& surroundings() {
  static const std::vector<std::unique_ptr<TempFile>> files = [] {
    std::vector<std::unique_ptr<TempFile>> made;
    const fs::path library = dataDir() / "materials" / "library";
    const auto add = [&](const std::string& name, Bytes bytes) {
      const TempFile probe(".probe", {});
      fs::create_directories((probe.path().parent_path() / name).parent_path());
      made.push_back(std::make_unique<TempFile>(name, bytes));
    };
    const auto copy = [&](const std::string& from, const std::string& to) {
      const std::string text = fileText(library / from);
      add("library/" + to, bytesOf(text));
    };
    for (const char* m : {"merl/gold-paint.toml", "merl/alum-bronze.toml", "merl/teflon.toml", "rgl-epfl/acrylic_felt_green.toml",
                          "rgl-epfl/spectralon.toml", "nielsen2015/bluebook.toml"})
      copy(m, m);
    copy("merl/teflon.toml", "other/teflon.toml");
    add("perceptual/PerceptualDistances.csv", bytesOf("\"METHOD\";\"BRDF\";\"DISTANCE\"\n\"ABC\";\"gold-paint\";0.3\n"));
    add("perceptual/MaterialType.csv", bytesOf("BRDF;Type\ngold-paint;Metal\n"));
    add("map.hdr", bytesOf("#?RADIANCE\n"));
    add("scene.gltf", bytesOf("{}"));
    add("scene.glb", bytesOf("glTF"));
    return made;
  }();
  return files;
}

}  // namespace

void studyEntry(Bytes data) {
  (void)surroundings();
  const TempFile file("study.toml", data);
  const fs::path folder = file.path().parent_path();
  const app::StudyFile study = app::loadStudyFile(file.path(), folder / "library");
  const study::StudyPlan& plan = study.plan;

  // The plan as claimStudyFolder writes it, read back as --analyse and glossy report read it.
  const fs::path out = folder / "study-out";
  fs::create_directories(out);
  {
    const std::string json = study::planJson(plan);
    const TempFile written("study-out/study.json", bytesOf(json));
    try {
      if (study::planJson(study::readPlan(out)) != json) throw std::logic_error("a study's plan reads back as another plan");
    } catch (const InputError& e) {
      throw std::logic_error(std::string("a study's plan does not read back: ") + e.what());
    }
  }

  app::checkImageMemory(study.job.settings.width, study.job.settings.height, int(study.job.settings.panels.size()),
                       app::kSheetBytesPerPanelPixel);
  for (const study::PlannedMaterial& m : plan.materials) (void)app::sheetCost(loadMaterialFile(m.file), study.job);
  for (size_t s = 0; s < plan.scenes.size(); ++s)
    for (size_t l = 0; l < plan.lightings.size(); ++l) {
      (void)study.sceneOptions(s, l);
      for (const study::PlannedMaterial& m : plan.materials) (void)study::sheetPath(plan.scenes[s], plan.lightings[l], m.name);
    }
}

}  // namespace glossy::fuzz
