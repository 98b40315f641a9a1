// The images the site shows of a sheet, cut from the sheet's PNG — glossy sheet draws its panels at the top,
// in their EXR boxes, × 2^exposure and sRGB-encoded — so the site holds each of its pixels once:
//   - each panel in its box as a PNG of its own: the compare view flicks between them (a model and the
//     measured panel at the same exposure, nothing but the BRDF changes), and side by side in their boxes
//     they are the top of the sheet;
//   - the sheet below the panels (labels, figures, error maps, legend) as one PNG.
#pragma once

#include <filesystem>
#include <vector>

namespace glossy {
struct SheetRecord;
}

namespace glossy::report {

struct SheetPixels {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // 8-bit RGB, interleaved, row 0 at the top
};

// Decodes the sheet's PNG (its size already checked against the EXR by readSheetRecord). Throws InputError
// naming the PNG when its pixels cannot be read.
SheetPixels readSheetPixels(const SheetRecord& sheet);

// Writes every panel's image (layout::panelImage) and, when the PNG reaches below the panels, the rest
// (layout::sheetLowerImage) into `folder`, atomically.
void writeSheetImages(const SheetRecord& sheet, const SheetPixels& pixels, const std::filesystem::path& folder);

}  // namespace glossy::report
