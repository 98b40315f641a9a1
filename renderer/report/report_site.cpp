// Building the report site (report_site.h).
#include "renderer/report/report_site.h"

#include "renderer/util/atomic_file.h"
#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/output/owned_folder.h"
#include "renderer/plot/plot_output.h"
#include "renderer/report/index_page.h"
#include "renderer/report/input_folder.h"
#include "renderer/report/material_page.h"
#include "renderer/report/plot_index.h"
#include "renderer/report/plot_picture.h"
#include "renderer/report/sheet_images.h"
#include "renderer/report/sheet_record.h"
#include "renderer/report/site_assets.h"
#include "renderer/report/site_layout.h"

#include <algorithm>
#include <map>
#include <set>

namespace glossy::report {

namespace fs = std::filesystem;

namespace {

// A plot's SVG or CSV is copied as it is; the largest glossy plot writes is a few MB.
constexpr std::uintmax_t kMaxPlotFileBytes = std::uintmax_t(256) << 20;

void checkPlotKinds(const std::vector<std::string>& kinds) {
  std::string known;
  for (const char* k : plot::kPlotKinds) known.append(known.empty() ? "" : ", ").append(k);
  for (const std::string& kind : kinds)
    if (std::find(plot::kPlotKinds.begin(), plot::kPlotKinds.end(), kind) == plot::kPlotKinds.end())
      throw InputError("--plot-kinds: '" + shortened(kind) + "' is not a kind of plot (" + known + ")");
}

// The plots of one material as the site shows them: the kinds asked for, the data files if asked for, and
// each figure's shown file named.
PlotIndex sitePlots(PlotIndex index, const ReportOptions& o) {
  if (!o.plotKinds.empty())
    std::erase_if(index.figures, [&](const PlotFigure& f) {
      return std::find(o.plotKinds.begin(), o.plotKinds.end(), f.kind) == o.plotKinds.end();
    });
  std::set<std::string> data;
  for (PlotFigure& f : index.figures) {
    if (!o.plotData) {
      f.csv.clear();
      if (!f.png.empty()) f.svg.clear();
    }
    for (const std::string* file : {&f.svg, &f.csv})
      if (!file->empty()) data.insert(*file);
  }
  for (PlotFigure& f : index.figures) {
    if (!f.png.empty()) checkPlotPicture(index.folder / f.png);
    f.shown = f.png.empty() ? f.svg : sitePictureName(f.png, data);
  }
  return index;
}

}  // namespace

ReportResult writeReport(const ReportOptions& options) {
  // Everything is checked before anything is written: the destination first, then every input.
  OwnedFolder site(options.site, layout::kGenerator, "-o");
  checkPlotKinds(options.plotKinds);
  const std::vector<SheetRecord> sheets = readSheetFolder(options.sheetsDir);
  checkSameSettings(sheets);
  for (const SheetRecord& s : sheets) readSheetPixels(s);  // a PNG whose header reads but whose pixels do not
  std::map<std::string, PlotIndex> plots;
  if (options.plotsDir) {
    std::error_code ec;
    if (!fs::is_directory(*options.plotsDir, ec)) throw InputError(options.plotsDir->string() + ": no such folder (PLOTS_DIR)");
    for (const SheetRecord& s : sheets)
      if (fs::exists(fs::symlink_status(*options.plotsDir / s.name / "plots.json", ec)))
        plots.emplace(s.name, sitePlots(readPlotIndex(*options.plotsDir, *options.plotsDir / s.name), options));
  }

  // The files the site will hold, so the folder's manifest can list them before the first is written.
  std::vector<std::string> files = {layout::kIndex, layout::kStyle, layout::kScript};
  for (const SheetRecord& s : sheets) {
    const std::string folder = layout::materialFolder(s.name) + "/";
    files.push_back(layout::materialPage(s.name));
    for (const PanelRecord& p : s.panels) files.push_back(folder + layout::panelImage(p.layer));
    if (s.panelsBottom < s.pngHeight) files.push_back(folder + layout::sheetLowerImage());
    if (const auto it = plots.find(s.name); it != plots.end())
      for (const PlotFigure& f : it->second.figures)
        for (const std::string* file : {&f.shown, &f.svg, &f.csv})
          if (!file->empty()) files.push_back(folder + layout::plotFile(*file));
  }
  site.plan(files);

  ReportResult result;
  result.materials = sheets.size();
  std::set<fs::path> written;
  for (size_t k = 0; k < sheets.size(); ++k) {
    const SheetRecord& s = sheets[k];
    const fs::path folder = site.path(layout::materialFolder(s.name));
    fs::create_directories(folder);
    writeSheetImages(s, readSheetPixels(s), folder);
    result.images += s.panels.size() + 1;
    const auto it = plots.find(s.name);
    if (it != plots.end() && !it->second.figures.empty()) {
      fs::create_directories(folder / "plots");
      for (const PlotFigure& f : it->second.figures) {
        if (!f.png.empty() && written.insert(folder / layout::plotFile(f.shown)).second) {
          writeSitePicture(it->second.folder / f.png, folder / layout::plotFile(f.shown));
          ++result.plots;
        }
        for (const std::string* file : {&f.svg, &f.csv})
          if (!file->empty() && written.insert(folder / layout::plotFile(*file)).second) {
            writeFileAtomically(folder / layout::plotFile(*file),
                                readInputFile(*options.plotsDir, it->second.folder / *file, kMaxPlotFileBytes, "plot file"));
            ++result.plots;
          }
      }
    }
    writeFileAtomically(folder / "index.html", materialPage(s, it == plots.end() ? nullptr : &it->second, k ? &sheets[k - 1] : nullptr,
                                                            k + 1 < sheets.size() ? &sheets[k + 1] : nullptr));
  }
  fs::create_directories(site.path("assets"));
  writeFileAtomically(site.path(layout::kStyle), siteStyleSheet());
  writeFileAtomically(site.path(layout::kScript), siteScript());
  writeFileAtomically(site.path(layout::kIndex), indexPage(sheets));  // last: the index links only to pages already there
  site.finish();
  return result;
}

}  // namespace glossy::report
