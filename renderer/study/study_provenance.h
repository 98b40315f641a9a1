// What a study's results stand on, as results.json records it and its methods paragraph cites it
// (docs/study.md, "Provenance"): the glossy that made them (version and commit), every setting of the
// sheets and the analysis, each lighting and scene with the digest of its contents, each material's
// database and whether its measured panel is a table or an NBRDF reconstruction, and each model's fits by
// source (the paper's, or glossy's own). The study command fills it from the study file it ran; the
// analysis adds what the rows say (the fits) and the glossy it is.
#pragma once

#include "renderer/study/study_row.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace glossy::study {

struct LightingProvenance {
  std::string name;         // the study file's name
  std::string kind;         // "sky", "map" or "constant"
  std::string description;  // the environment's own: "default sky", "studio_small_09_1k.hdr rotated 90°", "constant 0.8,0.8,0.9"
  std::string map;          // a map's file name (not its path: the folder it lies in is not the lighting)
  std::string digest;       // a map's contents (renderer/util/digest.h), as the sheets record it
  double rotate = 0.0;      // degrees about +Y
};

struct SceneProvenance {
  std::string name;     // the study file's name
  std::string builtin;  // "preview", "sphere", or "" for a scene of the user's
  std::string file;     // its glTF's file name
  std::string camera;   // "" (the scene's first), a name, or "auto"
  std::string digest;   // the scene's contents, as the sheets record it
};

struct MaterialProvenance {
  std::string name, database;
  // "MERL table", "NBRDF reconstruction" or "none" (no measured data found: its sheets' rows have no r*).
  std::string measured;
  std::string measuredSource;  // how sheets label it, e.g. "MERL", "RGL-EPFL (NBRDF reconstruction)"
  std::string measuredDigest;  // the measured data's contents; "" for none
};

struct SettingsProvenance {
  int width = 0, height = 0;
  int spp = 0;             // the samples per pixel, or with a time or a target error their cap
  bool sppGiven = false;   // settings.spp was given (else the cap of a time or a target error)
  double seconds = 0.0;    // settings.time: seconds per panel; 0: none
  double targetError = 0.0;  // settings.target-error: the half-width every r* interval is rendered to; 0: none
  std::uint64_t seed = 0;
  int maxDepth = 0, lightSamples = 0, bsdfSamples = 0;
  double exposure = 0.0;
  std::string panels;  // the --panels list
  bool half = false;
  int resamples = 0;   // analysis.resamples
  std::string reference;  // analysis.reference
};

struct StudyProvenance {
  std::string studyFile;  // the study file's name
  std::string studyText;  // its bytes as read: the analysis keeps them as analysis/study.toml
  SettingsProvenance settings;
  std::vector<LightingProvenance> lightings;  // in the plan's order
  std::vector<SceneProvenance> scenes;
  std::vector<MaterialProvenance> materials;  // sorted by name
};

// The file the analysis copies the study file to, within the analysis folder.
inline constexpr const char* kStudyFileCopy = "study.toml";

// results.json's "provenance": the settings, lightings, scenes, databases (each with its materials' count
// by kind of measured panel) and materials.
nlohmann::ordered_json provenanceJson(const StudyProvenance& p);

// results.json's "fits": per model label, each fit its rows carry with its source ("published": the
// paper's; "glossy": glossy's own), the databases and the number of materials it covers.
nlohmann::ordered_json fitsJson(std::span<const StudyRow> rows);

// results.json's "glossy": the version and commit of the glossy that wrote it.
nlohmann::ordered_json glossyJson();

}  // namespace glossy::study
