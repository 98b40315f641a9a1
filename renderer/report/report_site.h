// `glossy report`: a static site over a folder of sheets (and optionally the plots of `glossy plot`),
// self-contained so it can be moved, zipped or opened from file:// offline (site_layout.h). Everything is
// read and checked before anything is written. The site's folder is glossy's own (its manifest,
// renderer/output/owned_folder.h): a run writes into a missing or empty folder or an earlier report,
// replaces only the files the earlier report wrote, and writes the index last.
//
// Given the output folder of `glossy study` (study::isStudyFolder) instead of a folder of sheets, the site is
// the study's (study_page.h): its page at the top, and a site as above of each scene and lighting's sheets
// under sheets/SCENE/LIGHTING/.
#pragma once

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace glossy::report {

struct ReportOptions {
  std::filesystem::path sheetsDir;
  std::filesystem::path plotsDir;  // empty: none
  std::filesystem::path site;
  // Only the plots of these kinds ("theta_h", "polar", ...; plot::kPlotKinds); empty: all.
  std::vector<std::string> plotKinds;
  std::string plotKindsName = "--plot-kinds";  // what a message calls plotKinds
  // Copy each figure's SVG and CSV beside its picture (and link them); false: the picture alone.
  bool plotData = false;
};

struct ReportResult {
  size_t sheets = 0, images = 0, plots = 0;
  std::set<std::string> materials;  // a study has a sheet of each under every lighting and scene
};

// Throws InputError (naming the file or option) for bad input: SHEETS_DIR missing or without sheets, a sheet
// that cannot be read, two sheets of one material or made with different settings, PLOTS_DIR missing, a
// malformed plots.json, an unknown plot kind, SITE a file or a folder that is not an earlier report.
ReportResult writeReport(const ReportOptions& options);

}  // namespace glossy::report
