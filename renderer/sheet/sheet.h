// A material sheet: the supplement's comparison grid for one material —
//   Measured | Microfacet E2 | Smooth E2 | AS E1 | AS E2 | CT E1 | CT E2
// — every panel rendered with the same scene, camera, environment, seed and sample budget, and how close
// each analytic panel comes to the measured one (relative RMSE over the object's pixels, mean luminance
// ratio). The panels replace the material of the scene's object (the meshes whose glTF material binds a
// glossy material; every non-emissive mesh when none does); the backdrop keeps its own.
#pragma once

#include "materials/merl/merl_table.h"
#include "materials/params/material_file.h"
#include "renderer/integrator/path_tracer.h"

#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace glossy {

struct SheetPanel {
  std::string layer;  // EXR layer: "measured", "microfacet_E2", ...
  std::string label;  // for people: "Measured", "Microfacet E2", ...
  std::string fit;    // MODEL:METRIC; empty for the measured panel

  static SheetPanel measured();
  // Layer "cook_torrance_E2", label "CT E2": the model's short label (registry.h) and the metric.
  static SheetPanel ofFit(const FitId& fit);
};
// The supplement's comparison grid, the one list of it: Measured, then its six fits in its order.
std::span<const SheetPanel> sheetPanels();

struct SheetSettings {
  int width = 256, height = 256;  // per panel
  int spp = 64;
  double secondsPerPanel = 0.0;   // > 0: render progressively until this wall-clock budget is spent
  uint32_t seed = 0;
  int threads = 0;
  int maxDepth = 8;
  bool progress = true;
  std::vector<SheetPanel> panels{sheetPanels().begin(), sheetPanels().end()};
};

// What every panel shares.
struct SheetScene {
  const SceneDescription* description;
  const EmbreeScene* bvh;
  const Environment* environment;
  const Camera* camera;
  std::vector<Brdf> baseBrdfs;      // per scene material, as the scene binds them
  std::vector<bool> isObject;       // per scene material: replaced by each panel's BRDF
};
// The object: materials with an extras.glossy binding, else every non-emissive one.
SheetScene makeSheetScene(const SceneDescription& description, const EmbreeScene& bvh,
                          const Environment& environment, const Camera& camera);

struct PanelRender {
  SheetPanel panel;
  bool empty = true;
  std::string note;  // why a panel is empty, or where its data came from
  RgbImage image;    // width × height; black when empty
  int spp = 0;
  double seconds = 0.0;
  uint64_t droppedSamples = 0;
  double relativeRmse = -1.0, luminanceRatio = -1.0;  // against the measured panel; < 0 when there is none
  double brdfE1 = -1.0, brdfE2 = -1.0;  // the fit's E1, E2 against the measured table (docs/fitting.md); < 0: none
};

struct Sheet {
  std::string material;
  std::vector<PanelRender> panels;  // in SheetSettings::panels order
  std::vector<char> objectMask;     // per panel pixel: the primary ray hits the object
  RgbImage grid;                    // the panels side by side, panels × width by height
  const PanelRender* measured() const;  // null when the grid has no measured panel
  bool hasMeasured() const { return measured() && !measured()->empty; }
};

// `measured` may be null (its panel is then empty, with `measuredNote` saying why).
Sheet renderSheet(const SheetScene& scene, const MaterialFile& material, std::shared_ptr<const MerlTable> measured,
                  const std::string& measuredNote, const SheetSettings& settings);

// ‖panel − reference‖ / ‖reference‖ over the masked pixels and all three channels; and Σ lum(panel) / Σ lum(reference).
double relativeRmse(const RgbImage& panel, const RgbImage& reference, const std::vector<char>& mask);
double luminanceRatio(const RgbImage& panel, const RgbImage& reference, const std::vector<char>& mask);

// The EXR: default RGB layer = the grid; layer <panel>.R/G/B = that panel at its place in the grid (black
// elsewhere: EXR layers share one size); glossy:* metadata including each panel's box, spp and errors.
void writeSheetExr(const Sheet& sheet, const std::filesystem::path& path, std::vector<ImageAttribute> metadata, PixelType type);
// The preview: panels × 2^exposure, sRGB, with a label strip under each (name, error figures or why it is
// empty). fontPath empty: OIIO's default font search.
void writeSheetPng(const Sheet& sheet, const std::filesystem::path& path, double exposure, const std::string& fontPath);
// The error table for stdout.
std::string errorTable(const Sheet& sheet);

}  // namespace glossy
