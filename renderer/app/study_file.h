// A study file (docs/study.md): the materials of a study (globs over the library's databases), its named
// lightings and scenes, one settings block for every sheet and the analysis's options, read from TOML and
// checked whole before any work — an unknown key, a glob that matches nothing, a missing environment map, a
// non-finite or out-of-range setting is an InputError "FILE:LINE: KEY: ..." naming the file and the key.
// Relative paths resolve against the study file's folder; names from the file (lightings, scenes) must be
// plain names (materials/params/material_name.h), as they name the study's folders.
#pragma once

#include "renderer/app/scene_options.h"
#include "renderer/app/sheet_job.h"
#include "renderer/study/study_plan.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace glossy::app {

struct StudyLighting {
  std::string name;
  std::string env, envConstant;  // a map's path (absolute), or "R,G,B"; neither: the built-in sky
  double rotate = 0.0;
};

struct StudyScene {
  std::string name;
  std::string gltf;    // absolute
  std::string camera;  // "" (the scene's first), a name, or "auto"
  std::string builtin;  // "preview" or "sphere" for a scene glossy ships, else ""
};

// The r* half-width a study renders each sheet to when its file sets no cost (settings.spp or time) and no
// other target: the precision at which render noise stops biasing a study's figures. At a fixed 64 spp
// (32² panels) a sharp lobe's r* usually reads low and the study's correlations weaker; rendered to ±0.05
// they match a reference rendered to ±0.02 (bench/study-coverage; docs/study.md, "Render noise").
inline constexpr double kStudyTargetError = 0.05;

struct StudyFile {
  std::filesystem::path path;
  std::string text;  // its bytes as read and parsed: what the analysis keeps a copy of
  study::StudyPlan plan;
  std::vector<StudyLighting> lightings;  // in the plan's order
  std::vector<StudyScene> scenes;        // likewise
  SheetJob job;                          // every sheet's settings (scene and lighting set per sheet)
  bool sppGiven = false;
  // The analysis (renderer/study/study_analysis.h).
  int resamples = 2000;
  std::string referenceModel = "Microfacet E2";

  // The scene options of one sheet: scene `scene`, lighting `lighting` (indices).
  SceneOptions sceneOptions(size_t scene, size_t lighting) const;
};

// A database folder's label as StudyRow::database gives it ("rgl-epfl" → "RGL-EPFL"); an unknown folder's own name.
std::string databaseOfFolder(const std::string& folder);

// Reads and checks `path`; `library` is the material library (a folder per database) its globs range over.
StudyFile loadStudyFile(const std::filesystem::path& path, const std::filesystem::path& library);

}  // namespace glossy::app
