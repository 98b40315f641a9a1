// A sheet's panels as PNGs of their own, for the report's compare view and thumbnails: each panel's box cut
// from its EXR layer and shown as the sheet's PNG shows it — × 2^exposure, sRGB-encoded — so that toggling
// between a model panel and the measured one changes nothing but the BRDF.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace glossy::report {

struct PanelRecord;

// Reads the panels' layers of `exr` in one pass over its scanlines (a sheet's layers share its compressed
// blocks, so reading them one by one would decompress the file once per panel) and writes panel k to
// png(panels[k]) (atomically). Throws InputError naming the EXR when its pixels cannot be read.
void writePanelPngs(const std::filesystem::path& exr, const std::vector<const PanelRecord*>& panels, double exposure,
                    const std::function<std::filesystem::path(const PanelRecord&)>& png);

}  // namespace glossy::report
