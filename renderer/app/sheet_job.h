// One material's sheet without the command line: the options a run of `glossy sheet` or `glossy sheets`
// shares, the scene every sheet of a run renders (Stage), the rendering of one sheet and the writing of its
// EXR and PNG. The command line and the Python module (renderer/python/) both use it, so the two make the
// same sheet.
#pragma once

#include "renderer/app/scene_options.h"
#include "renderer/sheet/sheet.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace glossy::app {

struct SheetJob {
  SceneOptions scene;
  std::string merlDir;
  double exposure = 0.0;  // of the PNG
  bool half = false;      // of the EXR
  SheetSettings settings;
};

// --target-error alone stops at this many samples per pixel, saying so, rather than run for days after a
// target too fine to reach; --spp or --time set another cap.
inline constexpr int kTargetErrorSppCap = 4096;

// The sample cap of a run whose --spp was or was not given: --spp's value; with --time, as many as the
// time allows; with --target-error alone, kTargetErrorSppCap.
void applyPassLimits(SheetSettings& settings, bool sppGiven);

// What every sheet of one run shares: the scene, its BVH, the environment, the camera.
struct Stage {
  SceneDescription description;
  Camera camera;
  EmbreeScene bvh;
  Environment environment;
  std::string inputs;  // SceneOptions::inputs: what the pixels take from the scene and lighting

  // `aspect`: a panel's width / height, which the automatic camera frames for.
  Stage(const SceneOptions& o, double aspect)
      : description(loadGltf(o.scenePath())), camera(o.cameraOf(description, aspect)), bvh(description),
        environment(o.environment()), inputs(o.inputs(description, environment)) {}
};

struct MadeSheet {
  MaterialFile material;
  std::string explicitMeasured;  // the measured data given for it, if any
  Sheet sheet;
  double seconds = 0.0;  // rendering and comparing
};

// Loads the material and its measured data (`explicitMeasured`, else the file's own: measuredOf), then
// renders its sheet. InputError naming the file for bad input, before rendering. A --target-error the
// passes stopped short of is noted (renderer/util/notes.h), with the interval they reached.
MadeSheet makeMaterialSheet(const Stage& stage, const std::filesystem::path& materialPath, const SheetJob& job,
                            const std::string& explicitMeasured);
// The PNG beside `exr`, then the EXR with its metadata (the settings line resume compares last: a sheet whose
// EXR is whole is complete).
void writeSheetFiles(const MadeSheet& made, const Stage& stage, const SheetJob& job, const std::filesystem::path& exr);

// Everything a sheet's pixels depend on, as one line: glossy sheets keeps a sheet only if this matches.
// `stageInputs`: the Stage's inputs (SceneOptions::inputs), which a batch may know without building it.
std::string sheetSettings(const MaterialFile& m, const std::string& stageInputs, const SheetJob& job, const std::string& explicitMeasured);
inline std::string sheetSettings(const MaterialFile& m, const Stage& stage, const SheetJob& job, const std::string& explicitMeasured) {
  return sheetSettings(m, stage.inputs, job, explicitMeasured);
}

// Renders and writes one sheet (EXR, then PNG beside it); prints its error table on stdout and what it wrote
// on stderr.
void makeSheetFiles(const Stage& stage, const std::filesystem::path& materialPath, const SheetJob& job,
                    const std::filesystem::path& exr, const std::string& explicitMeasured);

// What became of one sheet of a batch (glossy sheets, glossy study).
enum class BatchSheet { Rendered, Complete, Busy };

// One sheet of a resumable batch: left to another run that holds it (its OutputLock: Busy), kept when it is
// complete with these settings (whyIncomplete: Complete), else rendered and written (Rendered), clearing
// the temporaries an interrupted write of it left. `tag` starts its lines on stderr ("[3/40] gold-paint").
// `stageInputs`: the inputs of the stage `stage()` gives (Stage::inputs), asked for only when the sheet is
// to be rendered, so that a batch builds a stage only for sheets that need one.
BatchSheet renderBatchSheet(const std::string& stageInputs, const std::function<const Stage&()>& stage,
                            const std::filesystem::path& materialPath, const SheetJob& job, const std::filesystem::path& exr,
                            const std::string& tag);

// The sheets of a batch in turn: sheet(k, tag) renders or keeps the k-th of costs.size() (renderBatchSheet),
// its tag "[k+1/count] NAME" with NAME = name(k); a line after each one rendered says the time to go — the
// time so far per unit of expected cost (`costs`, sheetCost) rendered, times the expected cost of what is
// left, as the sheets differ in cost and come in no order of it — and one at the end what became of them
// ("`who`: 3 sheets rendered, 1 already complete, in `folder`"). Returns how many were left to another run
// (Busy).
size_t renderBatch(const std::vector<double>& costs, const std::function<std::string(size_t)>& name,
                   const std::function<BatchSheet(size_t, const std::string&)>& sheet, const char* who, const std::string& folder);

// What a sheet costs, in analytic panels, for splitting a batch into shards (shard.h).
double sheetCost(const MaterialFile& m, const SheetJob& job);

}  // namespace glossy::app
