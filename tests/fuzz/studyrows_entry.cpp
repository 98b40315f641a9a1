// A study's rows as `glossy study --analyse` and `glossy report` make them (renderer/study/study_rows.h)
// and the analysis takes them (renderer/study/study_analysis.h). Nothing writes the rows to a file that
// is read back (rows.csv and rows.json are outputs only): the rows are read from the study's sheets, so the
// bytes are a sheet's EXR, OUT/sheets/preview/sky/alum-bronze.exr with a PNG beside it, in a study of that
// one sheet (OUT/study.json) with perceptual data. The PNG is 56 × 64 pixels, as the seeds' sheets' (`glossy
// sheet` at 8 × 8 pixels a panel): a sheet's PNG must be as wide as its EXR and reach below its panels, so a
// 1 × 1 PNG, as `sheet`'s, would turn down every sheet before its rows. The EXR's reading is `sheet`'s target; what this
// one adds is what the study makes of an accepted sheet: its panels made rows (the fit named in each
// panel, its figures, the closest ones and the tie, the size, samples and seed among its settings; the
// material's parameter file, the library's, deciding whose fit each is; its class from the perceptual
// table), then every statistic of the analysis over them, written into a folder as the command writes it,
// at the fewest bootstrap resamples a study file allows (the bootstraps are the time, not the code).
// rsvg-convert is kept off PATH, so the figures stay SVGs: the PNGs are another program's work, and its
// start-up was three quarters of the target's time.
#include "renderer/study/study_analysis.h"
#include "renderer/study/study_plan.h"
#include "renderer/study/study_rows.h"
#include "renderer/util/data_dir.h"
#include "tests/fuzz/fuzz_entries.h"
#include "tests/fuzz/fuzz_temp_dir.h"

#include <OpenImageIO/imageio.h>

#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace glossy::fuzz {

namespace {

namespace fs = std::filesystem;

Bytes bytesOf(std::string_view text) { return {reinterpret_cast<const uint8_t*>(text.data()), text.size()}; }

constexpr const char* kSheet = "rows/out/sheets/preview/sky/alum-bronze";

struct Study {
  std::vector<std::unique_ptr<TempFile>> files;
  fs::path out, perceptual;
  study::StudyPlan plan;
};

// The study around the sheet, made once for the process.
const Study& theStudy() {
  static const Study made = [] {
    ::setenv("PATH", "", 1);
    Study s;
    const TempFile probe(".probe", {});
    const fs::path dir = probe.path().parent_path();
    s.out = dir / "rows" / "out";
    s.perceptual = dir / "rows" / "perceptual";
    fs::create_directories(fs::path(dir / kSheet).parent_path());
    fs::create_directories(s.perceptual);
    fs::create_directories(s.out / study::kAnalysisFolder);
    const fs::path png = dir / (std::string(kSheet) + ".png");
    const std::vector<uint8_t> grey(56 * 64 * 3, 128);
    auto writer = OIIO::ImageOutput::create(png.string());
    // Not InputError: a failure here is the harness's, never the input's.
    if (!writer || !writer->open(png.string(), OIIO::ImageSpec(56, 64, 3, OIIO::TypeDesc::UINT8)) ||
        !writer->write_image(OIIO::TypeDesc::UINT8, grey.data()) || !writer->close())
      throw std::runtime_error("fuzz harness: cannot write " + png.string());
    s.files.push_back(std::make_unique<TempFile>(
        "rows/perceptual/PerceptualDistances.csv", bytesOf("\"METHOD\";\"BRDF\";\"DISTANCE\"\n\"ABC\";\"alum-bronze\";0.216666666666667\n")));
    s.files.push_back(std::make_unique<TempFile>("rows/perceptual/MaterialType.csv", bytesOf("BRDF;Type\nalum-bronze;Metal\n")));
    s.plan.study = dir / "study.toml";
    s.plan.materials.push_back({"alum-bronze", "MERL", dataDir() / "materials" / "library" / "merl" / "alum-bronze.toml"});
    s.plan.lightings = {"sky"};
    s.plan.scenes = {"preview"};
    s.plan.perceptualDir = s.perceptual;
    s.files.push_back(std::make_unique<TempFile>("rows/out/study.json", bytesOf(study::planJson(s.plan))));
    return s;
  }();
  return made;
}

}  // namespace

void studyrowsEntry(Bytes data) {
  const Study& s = theStudy();
  const TempFile exr(std::string(kSheet) + ".exr", data);
  const std::vector<study::StudyRow> rows = study::readStudyRows(s.out);
  study::AnalysisOptions options;
  options.resamples = 100;
  options.perceptualDir = s.plan.perceptualDir;
  const fs::path analysis = s.out / study::kAnalysisFolder;
  (void)study::analyseStudy(rows, options, analysis);
  // Emptied each time: the statistics, not the files, are what is fuzzed.
  for (const auto& f : fs::directory_iterator(analysis)) fs::remove_all(f.path());
}

}  // namespace glossy::fuzz
