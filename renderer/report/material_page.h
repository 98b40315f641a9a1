// A material's page in the report: the sheet as `glossy sheet` drew it (panels, labels and the error-map
// row), a compare view that swaps a model's panel with the measured one at the same exposure, the error
// figures with their intervals, each fit's parameters, and the material's plots from `glossy plot`.
#pragma once

#include "renderer/report/plot_index.h"
#include "renderer/sheet/sheet_record.h"

#include <string>

namespace glossy::report {

// `plots` null: no plots for this material. `previous`/`next`: neighbours in the index (may be null).
std::string materialPage(const SheetRecord& sheet, const PlotIndex* plots, const SheetRecord* previous, const SheetRecord* next);

}  // namespace glossy::report
