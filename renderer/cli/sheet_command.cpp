// glossy sheet / glossy sheets: a comparison grid (by default the supplement's) for one material, or for many
// (shared/spec/interfaces.md; renderer/sheet/sheet.h has the layout and the error figures).
#include "materials/core/input_error.h"
#include "renderer/util/notes.h"
#include "renderer/util/output_lock.h"
#include "materials/core/text.h"
#include "materials/params/material_file.h"
#include "renderer/app/destination.h"
#include "renderer/output/inside_folder.h"
#include "renderer/app/image_memory.h"
#include "renderer/app/material_files.h"
#include "renderer/app/shard.h"
#include "renderer/app/sheet_job.h"
#include "renderer/app/sheet_resume.h"
#include "renderer/cli/command.h"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <unistd.h>

namespace glossy::cli {

namespace {

struct SheetOptions : SheetJob {
  std::string material, measured, output = "out/sheet.exr";
  CLI::Option* spp = nullptr;
  std::string panels;
  CLI::Option* panelsOption = nullptr;
  // glossy sheets
  std::vector<std::string> inputs;
  std::string outDir = "out/sheets", shard;
};

void addRenderOptions(CLI::App* app, SheetOptions& o) {
  app->add_option("--merl-dir", o.merlDir, "Folder with MERL tables (else $GLOSSY_MERL_DIR)");
  addSceneOptions(app, o.scene);
  for (const OptionField& f : sheetOptionFields(o)) addOption(app, f);
  o.spp = app->get_option("--spp");
  o.panelsOption = app->add_option("--panels", o.panels,
                                   "The panels: a grid's name (" + gridNames() + "; docs/sheets.md) or a comma list of measured and "
                                   "MODEL:METRIC fits of any model glossy knows, in order; default: the supplement's, " +
                                   panelList(sheetPanels()));
  app->add_flag("--half", o.half, "Write half-float EXR (default: float); values above 65504 are clipped to it, and counted on stderr");
}

// --time renders until its budget is spent, --target-error until it is met or kTargetErrorSppCap; --spp caps
// either when given. Their passes each print a line. --panels is read here, before any work.
SheetOptions withPassLimits(const SheetOptions& o) {
  SheetOptions out = o;
  if (o.panelsOption->count() > 0) out.settings.panels = parsePanels(o.panels, "--panels");
  applyPassLimits(out.settings, o.spp->count() > 0);
  out.settings.passLines = true;
  return out;
}

int runSheet(const SheetOptions& options) {
  // Only EXR: the PNG is written beside it, under the same name with .png.
  checkOutputFile(options.output, "-o", {".exr"}, Folder::Create);
  const SheetOptions o = withPassLimits(options);
  checkImageMemory(o.settings.width, o.settings.height, int(o.settings.panels.size()), kSheetBytesPerPanelPixel);
  // Held until both files are in place: another run to the same -o is refused, not interleaved.
  const OutputLock lock(o.output, "-o");
  const Stage stage(o.scene, double(o.settings.width) / double(o.settings.height));
  SheetOptions single = o;
  single.settings.progress = isatty(STDERR_FILENO);
  makeSheetFiles(stage, o.material, single, o.output, o.measured);
  return 0;
}

int runSheets(const SheetOptions& options) {
  checkOutputFolder(options.outDir, "-o");
  const SheetOptions o = withPassLimits(options);
  checkImageMemory(o.settings.width, o.settings.height, int(o.settings.panels.size()), kSheetBytesPerPanelPixel);
  for (const std::string& in : o.inputs)
    if (std::error_code ec; !std::filesystem::is_directory(in, ec) && !std::filesystem::is_regular_file(in, ec))
      throw InputError(in + (std::filesystem::exists(in, ec) ? ": is not a material file or folder (a device, FIFO or socket)"
                                                             : ": no such material file or folder"));
  const std::vector<std::filesystem::path> files = app::materialFiles(o.inputs);
  const Shard shard = shardFrom(o.shard);
  // Validate every file, and where each sheet goes, before rendering any, so a typo fails in a second, not
  // after an hour. All files, not just this shard's: another shard writes to the same folder.
  const std::filesystem::path outDir = o.outDir;
  std::vector<std::string> names;
  std::vector<double> costs;
  std::map<std::string, std::filesystem::path> byName;
  for (const auto& f : files) {
    const MaterialFile m = loadMaterialFile(f);
    const std::string& name = m.name;
    if (auto [it, fresh] = byName.emplace(name, f); !fresh)
      throw InputError(it->second.string() + " and " + f.string() + ": both name the material '" + name +
                       "' (one sheet " + name + ".exr each)");
    std::error_code ec;
    for (const char* extension : {".exr", ".png"}) {
      const auto path = outDir / (name + extension);
      checkWriteInside(outDir, path, "-o");  // a symlink out of -o: refused, not followed
      if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
        throw InputError(path.string() + ": is in the way of " + f.string() + "'s sheet (not a file)");
    }
    names.push_back(name);
    costs.push_back(sheetCost(m, o));
  }
  const std::vector<size_t> mine = shardItems(costs, shard, "glossy sheets", "materials");

  const Stage stage(o.scene, double(o.settings.width) / double(o.settings.height));
  std::filesystem::create_directories(outDir);  // only once the scene and lighting options are known good
  SheetOptions batch = o;
  batch.settings.progress = false;
  std::vector<double> myCosts;
  for (size_t k : mine) myCosts.push_back(costs[k]);
  const size_t busy = renderBatch(
      myCosts, [&](size_t n) { return names[mine[n]]; },
      [&](size_t n, const std::string& tag) {
        return renderBatchSheet(stage.inputs, [&]() -> const Stage& { return stage; }, files[mine[n]], batch,
                                outDir / (names[mine[n]] + ".exr"), tag);
      },
      "glossy", o.outDir);
  if (busy == 0) return 0;
  // Not every sheet of this run is known to be complete: say so in the status too.
  std::fprintf(stderr, "glossy: %zu sheets left to the other run writing them; run again to check them\n", busy);
  return 1;
}

}  // namespace

Command addSheetCommand(CLI::App& parent) {
  auto o = std::make_shared<SheetOptions>();
  CLI::App* app = parent.add_subcommand(
      "sheet", "Render a material's comparison sheet: " + joined(sheetPanels(), " | ", [](const SheetPanel& p) { return p.label; }) +
                   ", into one layered EXR and a labelled PNG beside it, and print each model's error against the measured panel.");
  app->add_option("--material", o->material, "Material parameter file (TOML)")->required();
  app->add_option("--measured", o->measured, "MERL .binary (or .binary.xz) or .nbrdf network for the measured panel; default: "
                                             "the file's own, looked up in --merl-dir, $GLOSSY_MERL_DIR, the working folder, then "
                                             "the network embedded beside the material file (NAME.nbrdf)");
  addRenderOptions(app, *o);
  app->add_option("-o,--output", o->output, "Output EXR (the PNG is written beside it)")->capture_default_str();
  return {app, [o] { return runSheet(*o); }};
}

Command addSheetsCommand(CLI::App& parent) {
  auto o = std::make_shared<SheetOptions>();
  CLI::App* app = parent.add_subcommand(
      "sheets",
      "Render a sheet per material (default: every file of the material library) into OUTDIR/NAME.exr and .png; "
      "sheets already complete are skipped, so an interrupted run resumes.");
  app->add_option("inputs", o->inputs, "Material files or folders of them (default: the library)");
  app->add_option("-o,--output", o->outDir, "Output folder")->capture_default_str();
  app->add_option("--shard", o->shard,
                  "i/N: only shard i (0-based) of N, the materials split by expected cost; default: the job array's task "
                  "(Slurm, Kubernetes indexed Job, AWS Batch; docs/cluster.md)");
  addRenderOptions(app, *o);
  return {app, [o] { return runSheets(*o); }};
}

}  // namespace glossy::cli
