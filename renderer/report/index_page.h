// The report's index: one row per material with its thumbnail, a link to its page and the verdict, and
// one column group per model (relative RMSE, luminance ratio, ꟻLIP, E1, E2, closest), sortable by any
// column and filtered by name or verdict (site_assets.cpp); above it the per-model summary rows.
#pragma once

#include "renderer/report/model_summary.h"
#include "renderer/sheet/sheet_record.h"

#include <string>
#include <vector>

namespace glossy::report {

// The page's HTML. `sheets` in the order of the rows.
std::string indexPage(const std::vector<SheetRecord>& sheets);

// The panel a material's row shows as its thumbnail: the measured one, else the first that is not empty;
// null when every panel is empty.
const PanelRecord* thumbnailPanel(const SheetRecord& sheet);

}  // namespace glossy::report
