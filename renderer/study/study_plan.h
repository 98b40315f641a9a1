// What a study renders and where (docs/study.md): its materials with their databases, the names of its
// lightings and scenes, and the perceptual data it compares with. `glossy study` writes it as
// OUT/study.json before rendering, so that the sheets of OUT can be read back into rows — by the analysis
// and by `glossy report` — with nothing but the folder. The layout of OUT is decided here alone:
//   OUT/study.json                                   this plan
//   OUT/sheets/SCENE/LIGHTING/MATERIAL.exr, .png     the sheets, each folder one `glossy sheets` would make
//   OUT/analysis/                                    the statistics (study_analysis.h)
// SCENE, LIGHTING and MATERIAL are plain names (materials/params/material_name.h), checked where they are
// read, so none can name a path.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace glossy::study {

struct PlannedMaterial {
  std::string name;               // the material file's name, e.g. "gold-paint"
  std::string database;           // "MERL", "RGL-EPFL", "Nielsen 2015"
  std::filesystem::path file;     // its parameter file (absolute)
};

struct StudyPlan {
  // The study file (absolute): the study's identity. Its output folder is its own (study_folder.h); an
  // edited study file is the same study, another file another study. Empty in plans of older glossy.
  std::filesystem::path study;
  std::vector<PlannedMaterial> materials;   // sorted by name, each name once
  std::vector<std::string> lightings;       // the study file's names, sorted
  std::vector<std::string> scenes;          // likewise
  std::filesystem::path perceptualDir;      // absolute; empty: none
};

inline constexpr const char* kPlanFile = "study.json";
inline constexpr const char* kSheetsFolder = "sheets";
inline constexpr const char* kAnalysisFolder = "analysis";

// A sheet's EXR relative to OUT: sheets/SCENE/LIGHTING/MATERIAL.exr.
std::filesystem::path sheetPath(const std::string& scene, const std::string& lighting, const std::string& material);

// The plan as OUT/study.json holds it (stable text: the same plan gives the same bytes).
std::string planJson(const StudyPlan& plan);
// OUT/study.json read back; InputError naming the file when it is missing, not a glossy study plan, or holds
// a name that is not a plain name or is given twice.
StudyPlan readPlan(const std::filesystem::path& out);
// Whether `out` holds a file named study.json: what readers (glossy report) take for a study's folder. Not
// proof that glossy wrote it; a writer asks study_folder.h.
bool isStudyFolder(const std::filesystem::path& out);

}  // namespace glossy::study
