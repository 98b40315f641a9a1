// A sheet as a layered EXR: the grid, each panel's layer and error maps, and every figure as metadata.
#include "renderer/sheet/sheet.h"

#include "materials/core/text.h"
#include "materials/fitting/metric.h"
#include "renderer/image/flip.h"

#include <string>
#include <utility>
#include <vector>

namespace glossy {

namespace {

// The figures against the measured panel that a panel and the noise-floor row both carry, keyed
// PREFIX.relativeRmse and so on (what readSheetRecord reads back with Header::figures).
void addFigureAttributes(const std::string& prefix, const PanelFigures& f, const ErrorMaps& maps,
                         std::vector<ImageAttribute>& metadata) {
  if (f.compared) {
    metadata.push_back({prefix + ".relativeRmseNoisy", float(f.noisyRelativeRmse)});
    metadata.push_back({prefix + ".luminanceRatio", float(f.luminanceRatio)});
  }
  if (f.available) metadata.push_back({prefix + ".relativeRmse", float(f.relativeRmse)});
  if (f.hasCi) {
    metadata.push_back({prefix + ".relativeRmseCi", formatted("%.6g %.6g", f.relativeRmseCi.lo, f.relativeRmseCi.hi)});
    metadata.push_back({prefix + ".luminanceRatioCi", formatted("%.6g %.6g", f.luminanceRatioCi.lo, f.luminanceRatioCi.hi)});
  }
  if (maps.available) {
    metadata.push_back({prefix + ".flip", float(maps.flip)});
    metadata.push_back({prefix + ".deltaEItp", float(maps.deltaEItp)});
    metadata.push_back({prefix + ".ssim", float(maps.ssim)});
    if (maps.hasCi) {
      metadata.push_back({prefix + ".flipCi", formatted("%.6g %.6g", maps.flipCi.lo, maps.flipCi.hi)});
      metadata.push_back({prefix + ".deltaEItpCi", formatted("%.6g %.6g", maps.deltaEItpCi.lo, maps.deltaEItpCi.hi)});
      metadata.push_back({prefix + ".ssimCi", formatted("%.6g %.6g", maps.ssimCi.lo, maps.ssimCi.hi)});
    }
  }
}

// Panel k's box, label, colour, fit, note, spp and parameters (glossy:panel.LAYER.*), and its figures
// against the measured panel (glossy:error.LAYER.*).
void addPanelAttributes(const Sheet& sheet, size_t k, std::vector<ImageAttribute>& metadata) {
  const PanelRender& p = sheet.panels[k];
  const int w = sheet.panels.front().image.width, h = sheet.panels.front().image.height;
  const std::string key = "glossy:panel." + p.panel.layer;
  metadata.push_back({key + ".box", std::to_string(int(k) * w) + " 0 " + std::to_string(w) + " " + std::to_string(h)});
  metadata.push_back({key + ".label", p.panel.label});
  metadata.push_back({key + ".colour", p.panel.colour});
  metadata.push_back({key + ".fit", p.panel.fit.empty() ? std::string("measured") : p.panel.fit});
  metadata.push_back({key + ".empty", int(p.empty)});
  if (!p.note.empty()) metadata.push_back({key + ".note", p.note});
  if (!p.empty) metadata.push_back({key + ".spp", sheet.spp});
  const std::string error = "glossy:error." + p.panel.layer;
  addFigureAttributes(error, p.figures, p.maps, metadata);
  if (p.figures.available)
    metadata.push_back({error + ".noiseFree", p.figures.clamped ? std::string("clamped at 0: the estimate of the squared error was negative")
                                                                : std::string("yes")});
  if (p.brdfE1 >= 0.0) {
    metadata.push_back({error + ".E1", float(p.brdfE1)});
    metadata.push_back({error + ".E2", float(p.brdfE2)});
  }
  if (!p.params.empty()) metadata.push_back({key + ".params", p.params});
}

// The noise-floor row's figures, keyed like a panel's.
void addNoiseFloorAttributes(const Sheet& sheet, std::vector<ImageAttribute>& metadata) {
  const PanelRender& floor = sheet.noiseFloor;
  if (floor.empty || !floor.figures.compared) return;
  metadata.push_back({"glossy:noiseFloor.seed", formatted("%u", noiseFloorSeed(sheet.seed))});
  addFigureAttributes("glossy:noiseFloor", floor.figures, floor.maps, metadata);
}

}  // namespace

void writeSheetExr(const Sheet& sheet, const std::filesystem::path& path, std::vector<ImageAttribute> metadata, PixelType type) {
  const int w = sheet.panels.front().image.width, h = sheet.panels.front().image.height;
  std::vector<ExrLayer> layers = {{"", &sheet.grid}};
  std::vector<RgbImage> maps;  // each analytic panel's two maps, as one-channel images
  maps.reserve(2 * sheet.panels.size());
  std::string names;
  for (size_t k = 0; k < sheet.panels.size(); ++k) {
    const PanelRender& p = sheet.panels[k];
    layers.push_back({p.panel.layer, &p.image, int(k) * w});
    names += (names.empty() ? "" : ",") + p.panel.layer;
    if (p.maps.available)
      for (const auto& [suffix, values] : {std::pair{"_reldiff", &p.maps.relativeDifference}, std::pair{"_flip", &p.maps.flipMap}}) {
        RgbImage& map = maps.emplace_back(w, h);
        for (size_t i = 0; i < values->size(); ++i) map.pixels[3 * i] = (*values)[i];
        layers.push_back({p.panel.layer + suffix, &map, int(k) * w, true});
      }
    addPanelAttributes(sheet, k, metadata);
  }
  metadata.push_back({"glossy:panels", names});
  metadata.push_back({"glossy:panelSize", std::to_string(w) + "x" + std::to_string(h)});
  metadata.push_back({"glossy:errors",
                       sheet.hasMeasured()
                           ? std::string("against the measured panel, over the object's pixels: relativeRmse with the render noise taken out "
                                         "(cross-products of independent replicates), relativeRmseNoisy without, luminanceRatio; *Ci: 95 % "
                                         "intervals; E1, E2: the fit against the measured table on the grid ") + MetricGrid::describe()
                           : std::string("none: no measured panel")});
  metadata.push_back({"glossy:errorMaps",
                       formatted("<panel>_reldiff.Y: (Y_panel - Y_measured) / max(Y_measured, 0.01 mean Y_measured) over the "
                                 "object's pixels, 0 elsewhere (Y: Rec. 709 luminance); the PNG's second row shows it clamped "
                                 "to +/-%g. <panel>_flip.Y: HDR-FLIP (Andersson et al. 2021) of the panel against the measured "
                                 "panel, %g pixels per degree; flip: its mean over the object's pixels (render noise included: it "
                                 "raises the figure), flipCi: the render noise's 95 %% spread of it (jackknife over the "
                                 "replicates); glossy:flipNoiseFloor: the same figure between two halves of the measured "
                                 "panel's samples, what noise alone shows",
                                 kRelativeDifferenceRange, FlipSettings{}.pixelsPerDegree)});
  if (sheet.flipNoiseFloor >= 0.0) metadata.push_back({"glossy:flipNoiseFloor", float(sheet.flipNoiseFloor)});
  addNoiseFloorAttributes(sheet, metadata);
  if (!sheet.warnings.empty()) {
    std::string text;
    for (const std::string& w : sheet.warnings) text.append(text.empty() ? "" : "\n").append(w);
    metadata.push_back({"glossy:warnings", text});
  }
  metadata.push_back({"glossy:verdict", verdictText(sheet)});
  metadata.push_back({"glossy:replicates", sheet.replicates});
  metadata.push_back({"glossy:passes", sheet.passes});
  metadata.push_back({"glossy:bsdfSamples", sheet.bsdfSamples});
  metadata.push_back({"glossy:objectShare", float(sheet.objectShare)});
  writeLayeredExr(path, layers, metadata, type);
}

}  // namespace glossy
