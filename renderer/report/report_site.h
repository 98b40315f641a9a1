// `glossy report`: a static site over a folder of sheets (and optionally the plots of `glossy plot`),
// self-contained so it can be moved, zipped or opened from file:// offline (site_layout.h). Everything is
// read and checked before anything is written; the site is built in a temporary folder beside SITE and
// swapped into place at the end, so a reader never sees half a site and a failed run leaves SITE as it was.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace glossy::report {

struct ReportOptions {
  std::filesystem::path sheetsDir;
  std::optional<std::filesystem::path> plotsDir;
  std::filesystem::path site;
  // Only the plots of these kinds ("theta_h", "polar", ...); empty: all.
  std::vector<std::string> plotKinds;
  // Copy each figure's SVG and CSV beside its PNG (and link them); false: the picture alone, a lighter site.
  bool plotData = true;
};

struct ReportResult {
  size_t materials = 0, images = 0, plots = 0;
};

// Throws InputError (naming the file or option) for bad input: SHEETS_DIR missing or without sheets, a sheet
// that cannot be read, PLOTS_DIR missing, a malformed plots.json, SITE a file or a folder that is not a
// report (the site replaces only an earlier report or an empty folder).
ReportResult writeReport(const ReportOptions& options);

// Whether `folder` is empty or holds a site this command wrote (its index names the generator).
bool isReplaceableSite(const std::filesystem::path& folder);

}  // namespace glossy::report
