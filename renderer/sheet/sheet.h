// A material sheet: a comparison grid for one material (comparison_grid.h: by default the supplement's,
//   Measured | Microfacet E2 | Smooth E2 | AS E1 | AS E2 | CT E1 | CT E2)
// — every panel rendered with the same scene, camera, environment, seed and samples, and how close each
// analytic panel comes to the measured one over the object's pixels: the relative RMSE with the render
// noise taken out and the luminance ratio, each with a 95 % interval, and the closest model when the
// intervals say so (comparison.h). The panels replace the material of the scene's object (the meshes whose
// glTF material binds a glossy material; every non-emissive mesh when none does); the backdrop keeps its
// own. The panels are rendered together (renderPanels): one path per sample up to the object, where each
// panel continues with its own BRDF.
//
// Samples come in kReplicates independent replicates per pixel, each its own sample pattern: the figures'
// noise-free estimates and intervals are built from them. A panel's image is their mean.
#pragma once

#include "materials/merl/merl_table.h"
#include "materials/params/material_file.h"
#include "renderer/integrator/path_tracer.h"
#include "renderer/sheet/comparison.h"
#include "renderer/sheet/comparison_grid.h"
#include "renderer/sheet/error_maps.h"

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace glossy {

constexpr int kReplicates = 4;

// What a sheet file holds, as a number: it goes up when sheets gain layers or figures (2: the error maps and
// HDR-ꟻLIP; 3: the warnings and the noise-floor row), so that glossy sheets renders again a sheet made before, rather than resume past it.
constexpr int kSheetFormat = 3;  // 3: warnings, the noise-floor row

// A render's settings (width and height per panel; spp split evenly among the replicates, rounded up to fill
// them; control: the tiles of every pass, its total set when the passes are known up front, a fixed --spp;
// cancelled, renderSheet stops between tiles and throws Cancelled), and how the passes end.
struct SheetSettings : RenderSettings {
  // Every panel takes the same light samples at the object (--light-samples), not its BRDF's own count: the
  // panels then share those samples as well as the paths, their noise cancels in the differences against
  // the measured panel, and the intervals stay narrow (docs/sheets.md, "The panels are rendered together").
  SheetSettings() { width = height = 256; lightSamplesPerBrdf = false; }
  // > 0: render in passes until this wall-clock budget per panel (so × the panels rendered) is spent.
  double secondsPerPanel = 0.0;
  // > 0: render in passes until every analytic panel's relative-RMSE interval has at most this half-width,
  // or until spp or the time budget caps it.
  double targetError = 0.0;
  // With --time or --target-error: one line on stderr per pass (its samples, its widest interval), terminal
  // or not, so that a long run in a batch job's log shows how it goes.
  bool passLines = false;
  std::vector<SheetPanel> panels{sheetPanels().begin(), sheetPanels().end()};
};

// renderSheet stopped because its JobControl was cancelled.
struct Cancelled : std::runtime_error {
  Cancelled() : std::runtime_error("cancelled") {}
};

// What every panel shares.
struct SheetScene {
  const SceneDescription* description;
  const EmbreeScene* bvh;
  const Environment* environment;
  const Camera* camera;
  std::vector<Brdf> baseBrdfs;      // per scene material, as the scene binds them
  std::vector<bool> isObject;       // per scene material: replaced by each panel's BRDF
  std::vector<bool> objectMeshes;   // per mesh: its material is the object's (or it has none)

  // The scene of a panel: `brdf` on the object, the backdrop as bound.
  RenderScene withObject(const Brdf& brdf) const;
};
// The object: materials with an extras.glossy binding, else every non-emissive one.
SheetScene makeSheetScene(const SceneDescription& description, const EmbreeScene& bvh,
                          const Environment& environment, const Camera& camera);

struct PanelRender {
  SheetPanel panel;
  bool empty = true;
  std::string note;                  // why a panel is empty, or where its data came from
  RgbImage image;                    // width × height, the mean of the replicates; black when empty
  std::vector<RgbImage> replicates;  // independent estimates of the image, each from spp / replicates samples
  PanelFigures figures;              // against the measured panel (figures.compared false when there is none)
  double brdfE1 = -1.0, brdfE2 = -1.0;  // the fit's E1, E2 against the measured table (docs/fitting.md); < 0: none
  ErrorMaps maps;                    // against the measured panel (maps.available false when there is none)
  std::string params;                // the fit's parameters as in its file, "kd = [...]; ks = [...]; ..."; empty: none
};

struct Sheet {
  std::string material;
  std::vector<PanelRender> panels;  // in SheetSettings::panels order
  std::vector<char> objectMask;     // per panel pixel: the primary ray hits the object
  RgbImage grid;                    // the panels side by side, panels × width by height
  int spp = 0;                      // per pixel, every panel alike
  int replicates = 0;
  int passes = 0;
  int bsdfSamples = 1;              // at the object's vertices (light_count.h, sheetBsdfSamples)
  double seconds = 0.0;             // rendering all panels
  uint64_t droppedSamples = 0;      // non-finite samples, over all panels
  double objectShare = 0.0;         // of the paths: reached the object, where the panels part ways
  Verdict verdict;                  // indices into panels
  size_t skippedPixels = 0;         // object pixels left out of the figures: not finite
  uint32_t seed = 0;                // the render's (settings.seed)
  double flipNoiseFloor = -1.0;     // ꟻLIP of the measured panel's two halves (error_maps.h); < 0: none
  // The measured panel against an independent render of itself (seed noiseFloorSeed, the same samples per
  // replicate): every figure of a model that is exactly the measured BRDF, i.e. what noise alone shows.
  // empty when there is no measured panel.
  PanelRender noiseFloor;
  // What makes the figures or the verdict less than they seem ("noise is up to 93 % …: the intervals may be
  // too narrow; render more samples"); while one stands, no model is named closest (glossy:warnings).
  std::vector<std::string> warnings;
  double widestHalfWidth = 0.0;     // the widest relative-RMSE interval's half-width; Inf: no interval (no measured panel)
  const PanelRender* measured() const;  // null when the grid has no measured panel
  bool hasMeasured() const { return measured() && !measured()->empty; }
};

// The warnings the figures call for: noise above 80 % of a plain figure's square, where the intervals were
// seen to run narrow (docs/sheets.md, "Where the intervals hold").
std::vector<std::string> figureWarnings(const std::vector<PanelFigures>& figures);
// The verdict a sheet states: while a warning stands, no model is named closest ("no verdict: …"); a tie
// or no verdict stays as it is.
Verdict verdictUnderWarnings(Verdict verdict, const std::vector<std::string>& warnings);

// The seed of the noise-floor row's render: another sequence than the sheet's, fixed by it.
uint32_t noiseFloorSeed(uint32_t seed);

// `measured` may be null (its panel is then empty, with `measuredNote` saying why).
Sheet renderSheet(const SheetScene& scene, const MaterialFile& material, std::shared_ptr<const MerlTable> measured,
                  const std::string& measuredNote, const SheetSettings& settings);

// The EXR: default RGB layer = the grid; layer <panel>.R/G/B = that panel at its place in the grid (black
// elsewhere: EXR layers share one size); for each analytic panel with maps, <panel>_reldiff.Y and
// <panel>_flip.Y at the same place (error_maps.h); glossy:* metadata including each panel's box, figures and
// parameters.
void writeSheetExr(const Sheet& sheet, const std::filesystem::path& path, std::vector<ImageAttribute> metadata, PixelType type);
// The preview: panels × 2^exposure, sRGB, with a label strip under each (name, error figures or why it is
// empty); when the sheet has a measured panel, a second row of each model's relative-difference map over the
// object (diverging colours, ±kRelativeDifferenceRange) with the colour bar's legend under the measured panel.
// fontPath empty: OIIO's default font search.
void writeSheetPng(const Sheet& sheet, const std::filesystem::path& path, double exposure, const std::string& fontPath);
// The size of that PNG for `panels` panels of w × h: its width, and its height without and with the row of
// error maps and the strip under them (the noise floor and the warnings) (there when the sheet has a
// measured panel).
struct SheetPngSize {
  int width, height, heightWithMaps;
};
SheetPngSize sheetPngSize(int panelWidth, int panelHeight, int panels);
// "closest: Smooth E2", "tie: Smooth E2, Microfacet E2" or why there is no verdict.
std::string verdictText(const Sheet& sheet);
// The error table for stdout, with the noise-floor row and the warnings.
std::string errorTable(const Sheet& sheet);

}  // namespace glossy
