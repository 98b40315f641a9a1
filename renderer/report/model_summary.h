// The index's summary rows: per model (each analytic panel layer of the sheets), how often it is the
// closest to the measured panel — alone, or in a tie, counted apart — and the median of each error figure
// over the materials that have it.
#pragma once

#include "renderer/sheet/sheet_record.h"

#include <optional>
#include <string>
#include <vector>

namespace glossy::report {

struct ModelSummary {
  std::string layer, label, colour;
  int closest = 0;  // materials where this model alone is closest
  int ties = 0;     // materials where it shares the verdict with others
  int compared = 0; // materials with a relative RMSE for it
  std::optional<double> medianRelativeRmse, medianLuminanceRatio, medianFlip, medianE1, medianE2;
};

// The analytic layers of all sheets, in the order they first appear (the grid's order).
std::vector<std::string> modelLayers(const std::vector<SheetRecord>& sheets);

std::vector<ModelSummary> summarizeModels(const std::vector<SheetRecord>& sheets);

// The median of the values (mean of the middle two for an even count); nullopt when there are none.
std::optional<double> median(std::vector<double> values);

}  // namespace glossy::report
