// plots.json as `glossy report` reads it (renderer/report/plot_index.h): the index of a plots folder, every
// file it names checked to be a plain name of a file in that folder, then the material page drawn with its
// figures. The folder holds the files `glossy plot` writes for a few figures, so that an index naming them
// is accepted.
#include "renderer/report/material_page.h"
#include "renderer/report/plot_index.h"
#include "tests/fuzz/fuzz_entries.h"
#include "tests/fuzz/fuzz_temp_dir.h"

#include <memory>
#include <vector>

namespace glossy::fuzz {

namespace {

// The figure files, made once for the process: "theta_h.svg", "theta_h.png", "theta_h.csv", ...
const std::vector<std::unique_ptr<TempFile>>& figureFiles() {
  static const std::vector<std::unique_ptr<TempFile>> files = [] {
    std::vector<std::unique_ptr<TempFile>> made;
    const uint8_t byte = '0';
    for (const char* figure : {"theta_h", "albedo", "polar", "image_slice_measured", "image_slice_cook_torrance_E2"})
      for (const char* extension : {".svg", ".png", ".csv"})
        made.push_back(std::make_unique<TempFile>(std::string(figure) + extension, Bytes(&byte, 1)));
    return made;
  }();
  return files;
}

}  // namespace

void plotsEntry(Bytes data) {
  const std::filesystem::path folder = figureFiles().front()->path().parent_path();
  const TempFile index("plots.json", data);
  const report::PlotIndex plots = report::readPlotIndex(folder.parent_path(), folder);
  SheetRecord sheet;
  sheet.name = "alum-bronze";
  (void)report::materialPage(sheet, &plots, nullptr, nullptr);
}

}  // namespace glossy::fuzz
