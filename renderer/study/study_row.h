// One model's figures on one sheet of a study (docs/study.md): the unit `glossy study` reads from the
// sheets it rendered and hands to its statistics. A study is a table of these, one row per
// material × lighting × scene × model; the statistics group them by (material, lighting, scene) — a
// "sheet" — and compare the models within each.
#pragma once

#include <optional>
#include <string>

namespace glossy::study {

struct StudyRow {
  // What was compared.
  std::string material;       // the material's name, e.g. "gold-paint"
  std::string database;       // "MERL", "RGL-EPFL", "Nielsen 2015"
  std::string materialClass;  // "Metal", "CMetal" or "Dielectric" where a class table knows it, else ""
  std::string lighting;       // the study file's name for the lighting, e.g. "sky", "studio"
  std::string scene;          // the study file's name for the scene
  // The model: one analytic panel of the sheet.
  std::string layer;      // EXR layer, e.g. "cook_torrance_E2"
  std::string label;      // "CT E2": what tables and figures call the model
  std::string fit;        // "cook-torrance:E2" or "cook-torrance:E2:glossy"
  std::string fitMetric;  // "E1" or "E2": the metric the fit minimised
  std::string fitSource;  // "published" (the paper's) or "glossy" (glossy's own fit)
  // The fit's BRDF-space errors against the measured table, and the image-space figures against the
  // measured panel with their 95 % intervals (absent where the sheet has none).
  std::optional<double> e1, e2;
  std::optional<double> rrmse, rrmseLo, rrmseHi;  // noise-free relative RMSE r*
  // r* is 0 by clamping: the noise-free estimate of its square came out negative (the model is within the
  // render noise of the measured panel). Ranked as 0, drawn as 0, and counted (results.json).
  bool rrmseClamped = false;
  std::optional<double> flip, flipLo, flipHi;     // mean HDR-ꟻLIP over the object
  std::optional<double> deltaEItp, deltaEItpLo, deltaEItpHi;  // mean ΔE_ITP over the object (display-encoded)
  std::optional<double> ssim, ssimLo, ssimHi;                 // mean SSIM over the object (1: identical)
  std::optional<double> luminanceRatio;
  // The sheet's verdict as it concerns this model.
  bool closest = false;  // named closest: its interval separates it from every other model
  bool tied = false;     // among the models the verdict ties (closest is then false)
  std::string warning;   // the sheet's warning (e.g. intervals may be too narrow); "" when none
  // Where it came from and how it was rendered.
  std::string sheet;  // the sheet's EXR, relative to the study's output folder
  int width = 0, height = 0, spp = 0;
  unsigned long long seed = 0;
};

}  // namespace glossy::study
