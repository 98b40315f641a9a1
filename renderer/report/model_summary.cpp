// Per-model summary of a set of sheets (model_summary.h).
#include "renderer/report/model_summary.h"

#include <algorithm>

namespace glossy::report {

std::vector<std::string> modelLayers(const std::vector<SheetRecord>& sheets) {
  std::vector<std::string> layers;
  for (const SheetRecord& s : sheets)
    for (const PanelRecord& p : s.panels)
      if (!p.isMeasured() && std::find(layers.begin(), layers.end(), p.layer) == layers.end()) layers.push_back(p.layer);
  return layers;
}

std::optional<double> median(std::vector<double> values) {
  if (values.empty()) return std::nullopt;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

std::vector<ModelSummary> summarizeModels(const std::vector<SheetRecord>& sheets) {
  std::vector<ModelSummary> out;
  for (const std::string& layer : modelLayers(sheets)) {
    ModelSummary m;
    m.layer = layer;
    std::vector<double> rmse, lum, flip, e1, e2;
    for (const SheetRecord& s : sheets) {
      const PanelRecord* p = s.panel(layer);
      if (!p) continue;
      if (m.label.empty()) m.label = p->label;
      if (m.colour.empty()) m.colour = p->colour;
      const std::vector<std::string> closest = s.closestLayers();
      if (std::find(closest.begin(), closest.end(), layer) != closest.end()) ++(closest.size() == 1 ? m.closest : m.ties);
      if (p->relativeRmse.value) {
        rmse.push_back(*p->relativeRmse.value);
        ++m.compared;
      }
      if (p->luminanceRatio.value) lum.push_back(*p->luminanceRatio.value);
      if (p->flip.value) flip.push_back(*p->flip.value);
      if (p->e1) e1.push_back(*p->e1);
      if (p->e2) e2.push_back(*p->e2);
    }
    m.medianRelativeRmse = median(rmse);
    m.medianLuminanceRatio = median(lum);
    m.medianFlip = median(flip);
    m.medianE1 = median(e1);
    m.medianE2 = median(e2);
    out.push_back(std::move(m));
  }
  return out;
}

}  // namespace glossy::report
