// One material's sheet without the command line: the options a run of `glossy sheet` or `glossy sheets`
// shares, the scene every sheet of a run renders (Stage), the rendering of one sheet and the writing of its
// EXR and PNG. The command line and the Python module (renderer/python/) both use it, so the two make the
// same sheet.
#pragma once

#include "renderer/cli/scene_options.h"
#include "renderer/sheet/sheet.h"

#include <filesystem>
#include <string>
#include <vector>

namespace glossy::cli {

struct SheetJob {
  SceneOptions scene;
  std::string merlDir;
  double exposure = 0.0;  // of the PNG
  bool half = false;      // of the EXR
  SheetSettings settings;
};

// What every sheet of one run shares: the scene, its BVH, the environment, the camera.
struct Stage {
  SceneDescription description;
  Camera camera;
  EmbreeScene bvh;
  Environment environment;

  // `aspect`: a panel's width / height, which the automatic camera frames for.
  Stage(const SceneOptions& o, double aspect)
      : description(loadGltf(o.scenePath())), camera(o.cameraOf(description, aspect)), bvh(description),
        environment(o.environment()) {}
};

struct MadeSheet {
  MaterialFile material;
  std::string explicitMeasured;  // the measured data given for it, if any
  Sheet sheet;
  double seconds = 0.0;  // rendering and comparing
};

// Loads the material and its measured data (`explicitMeasured`, else the file's own: measuredOf), then
// renders its sheet. InputError naming the file for bad input, before rendering.
MadeSheet makeMaterialSheet(const Stage& stage, const std::filesystem::path& materialPath, const SheetJob& job,
                            const std::string& explicitMeasured);
// The PNG beside `exr`, then the EXR with its metadata (the settings line resume compares last: a sheet whose
// EXR is whole is complete).
void writeSheetFiles(const MadeSheet& made, const Stage& stage, const SheetJob& job, const std::filesystem::path& exr);

// Everything a sheet's pixels depend on, as one line: glossy sheets keeps a sheet only if this matches.
std::string sheetSettings(const MaterialFile& m, const Stage& stage, const SheetJob& job, const std::string& explicitMeasured);

}  // namespace glossy::cli
