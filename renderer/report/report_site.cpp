// Building the report site (report_site.h).
#include "renderer/report/report_site.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/params/material_name.h"
#include "renderer/output/input_folder.h"
#include "renderer/output/owned_folder.h"
#include "renderer/plot/plot_output.h"
#include "renderer/report/index_page.h"
#include "renderer/report/material_page.h"
#include "renderer/report/plot_index.h"
#include "renderer/report/plot_picture.h"
#include "renderer/report/sheet_images.h"
#include "renderer/report/site_assets.h"
#include "renderer/report/site_layout.h"
#include "renderer/report/study_page.h"
#include "renderer/sheet/sheet_record.h"
#include "renderer/study/study_plan.h"
#include "renderer/study/study_rows.h"
#include "renderer/util/atomic_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <set>

namespace glossy::report {

namespace fs = std::filesystem;

namespace {

// A plot's SVG or CSV is copied as it is; the largest glossy plot writes is a few MB.
constexpr std::uintmax_t kMaxPlotFileBytes = std::uintmax_t(256) << 20;

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

void writeSiteAssets(const fs::path& root) {
  fs::create_directories(root / "assets");
  writeFileAtomically(root / layout::kStyle, siteStyleSheet());
  writeFileAtomically(root / layout::kScript, siteScript());
}

// One folder of sheets as a site of its own (site_layout.h), under `prefix` of the whole site ("" or
// "sheets/SCENE/LIGHTING/").
struct SheetSite {
  std::vector<SheetRecord> sheets;
  std::map<std::string, PlotIndex> plots;
};

SheetSite readSheetSite(const fs::path& sheetsDir, const ReportOptions& options) {
  SheetSite s;
  s.sheets = readSheetFolder(sheetsDir);
  checkSameSettings(s.sheets);
  for (const SheetRecord& sheet : s.sheets) readSheetPixels(sheet);  // a PNG whose header reads but whose pixels do not
  if (!options.plotsDir.empty()) {
    std::error_code ec;
    if (!fs::is_directory(options.plotsDir, ec)) throw InputError(options.plotsDir.string() + ": no such folder (PLOTS_DIR)");
    for (const SheetRecord& sheet : s.sheets)
      if (fs::exists(fs::symlink_status(options.plotsDir / sheet.name / "plots.json", ec)))
        s.plots.emplace(sheet.name, sitePlots(readPlotIndex(options.plotsDir, options.plotsDir / sheet.name), options));
  }
  return s;
}

// The files the site of `s` will hold, so the folder's manifest can list them before the first is written.
void addSheetSiteFiles(const SheetSite& s, const std::string& prefix, std::vector<std::string>& files) {
  for (const char* f : {layout::kIndex, layout::kStyle, layout::kScript}) files.push_back(prefix + f);
  for (const SheetRecord& sheet : s.sheets) {
    const std::string folder = prefix + layout::materialFolder(sheet.name) + "/";
    files.push_back(prefix + layout::materialPage(sheet.name));
    for (const PanelRecord& p : sheet.panels) files.push_back(folder + layout::panelImage(p.layer));
    if (sheet.panelsBottom < sheet.pngHeight) files.push_back(folder + layout::sheetLowerImage());
    if (const auto it = s.plots.find(sheet.name); it != s.plots.end())
      for (const PlotFigure& f : it->second.figures)
        for (const std::string* file : {&f.shown, &f.svg, &f.csv})
          if (!file->empty()) files.push_back(folder + layout::plotFile(*file));
  }
}

void writeSheetSite(const SheetSite& s, const fs::path& root, const ReportOptions& options, ReportResult& result) {
  const std::vector<SheetRecord>& sheets = s.sheets;
  result.sheets += sheets.size();
  for (const SheetRecord& sheet : sheets) result.materials.insert(sheet.name);
  std::set<fs::path> written;
  for (size_t k = 0; k < sheets.size(); ++k) {
    const SheetRecord& sheet = sheets[k];
    const fs::path folder = root / layout::materialFolder(sheet.name);
    fs::create_directories(folder);
    writeSheetImages(sheet, readSheetPixels(sheet), folder);
    result.images += sheet.panels.size() + 1;
    const auto it = s.plots.find(sheet.name);
    if (it != s.plots.end() && !it->second.figures.empty()) {
      fs::create_directories(folder / "plots");
      for (const PlotFigure& f : it->second.figures) {
        if (!f.png.empty() && written.insert(folder / layout::plotFile(f.shown)).second) {
          writeSitePicture(it->second.folder / f.png, folder / layout::plotFile(f.shown));
          ++result.plots;
        }
        for (const std::string* file : {&f.svg, &f.csv})
          if (!file->empty() && written.insert(folder / layout::plotFile(*file)).second) {
            writeFileAtomically(folder / layout::plotFile(*file),
                                readInputFile(options.plotsDir, it->second.folder / *file, kMaxPlotFileBytes, "plot file"));
            ++result.plots;
          }
      }
    }
    writeFileAtomically(folder / "index.html", materialPage(sheet, it == s.plots.end() ? nullptr : &it->second, k ? &sheets[k - 1] : nullptr,
                                                            k + 1 < sheets.size() ? &sheets[k + 1] : nullptr));
  }
  writeSiteAssets(root);
  writeFileAtomically(root / layout::kIndex, indexPage(sheets));  // last: the index links only to pages already there
}

// A study's analysis files (OUT/analysis, recursively), relative to it; each part of each path a plain name,
// as they become the site's paths.
StudyFiles studyFiles(const fs::path& analysis) {
  StudyFiles out;
  std::error_code ec;
  if (!fs::is_directory(analysis, ec)) return out;
  std::vector<std::string> all;
  for (const auto& e : fs::recursive_directory_iterator(analysis)) {
    if (e.is_directory(ec)) continue;
    const fs::path relative = fs::relative(e.path(), analysis);
    for (const fs::path& part : relative)
      if (!isMaterialName(part.string()))
        throw InputError(e.path().string() + ": not a plain file name; the report copies only the analysis's own files");
    all.push_back(relative.generic_string());
  }
  std::sort(all.begin(), all.end());
  const std::set<std::string> names(all.begin(), all.end());
  for (const std::string& f : all) {
    const fs::path p = f;
    const std::string ext = p.extension().string();
    if (ext == ".svg" || (ext == ".png" && !names.count(fs::path(p).replace_extension(".svg").generic_string())))
      out.figures.push_back(f);
    else
      out.others.push_back(f);
    if (p.stem() == "summary" && (ext == ".txt" || ext == ".md"))
      out.summary = readInputFile(analysis, analysis / p, kMaxPlotFileBytes, "summary");
  }
  // The figures' captions, as the analysis wrote them; an analysis without them keeps the page's own.
  if (names.count("results.json")) {
    const nlohmann::json results =
        nlohmann::json::parse(readInputFile(analysis, analysis / "results.json", kMaxPlotFileBytes, "study results"), nullptr, false);
    if (results.is_object() && results.contains("figures") && results["figures"].is_array())
      for (const nlohmann::json& f : results["figures"])
        if (f.is_object() && f.contains("name") && f["name"].is_string() && f.contains("caption") && f["caption"].is_string())
          out.captions[f["name"].get<std::string>()] = f["caption"].get<std::string>();
  }
  return out;
}

ReportResult writeStudyReport(OwnedFolder& site, const ReportOptions& options) {
  const fs::path out = options.sheetsDir;
  const study::StudyPlan plan = study::readPlan(out);
  const std::vector<study::StudyRow> rows = study::readStudyRows(out, plan);
  std::vector<std::pair<std::string, SheetSite>> sheetSites;
  for (const std::string& scene : plan.scenes)
    for (const std::string& lighting : plan.lightings)
      sheetSites.emplace_back(study_layout::sheetsSite(scene, lighting),
                              readSheetSite(out / study::kSheetsFolder / scene / lighting, options));
  const fs::path analysis = out / study::kAnalysisFolder;
  const StudyFiles files = studyFiles(analysis);

  std::vector<std::string> planned = {layout::kIndex, layout::kStyle, layout::kScript};
  for (const auto& [prefix, s] : sheetSites) addSheetSiteFiles(s, prefix, planned);
  for (const std::vector<std::string>* list : {&files.figures, &files.others})
    for (const std::string& f : *list) planned.push_back(study_layout::analysisFile(f));
  site.plan(planned);

  ReportResult result;
  for (const auto& [prefix, s] : sheetSites) writeSheetSite(s, site.path(prefix), options, result);
  for (const std::vector<std::string>* list : {&files.figures, &files.others})
    for (const std::string& f : *list) {
      const fs::path to = site.path(study_layout::analysisFile(f));
      fs::create_directories(to.parent_path());
      writeFileAtomically(to, readInputFile(analysis, analysis / f, kMaxPlotFileBytes, "analysis file"));
    }
  writeSiteAssets(site.root());
  writeFileAtomically(site.path(layout::kIndex), studyPage(plan, rows, files));  // last, as the sheets' own indexes
  site.finish();
  return result;
}

}  // namespace

ReportResult writeReport(const ReportOptions& options) {
  // Everything is checked before anything is written: the destination first, then every input.
  OwnedFolder site(options.site, layout::kGenerator, "-o");
  plot::checkPlotKinds(options.plotKinds, options.plotKindsName);
  if (study::isStudyFolder(options.sheetsDir)) return writeStudyReport(site, options);
  const SheetSite sheets = readSheetSite(options.sheetsDir, options);
  std::vector<std::string> files;
  addSheetSiteFiles(sheets, "", files);
  site.plan(files);
  ReportResult result;
  writeSheetSite(sheets, site.root(), options, result);
  site.finish();
  return result;
}

}  // namespace glossy::report
