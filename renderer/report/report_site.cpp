// Building the report site (report_site.h).
#include "renderer/report/report_site.h"

#include "materials/core/atomic_file.h"
#include "materials/core/input_error.h"
#include "renderer/report/index_page.h"
#include "renderer/report/material_page.h"
#include "renderer/report/panel_png.h"
#include "renderer/report/plot_index.h"
#include "renderer/report/sheet_record.h"
#include "renderer/report/site_assets.h"
#include "renderer/report/site_layout.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace glossy::report {

namespace fs = std::filesystem;

namespace {

// A folder beside the site that is removed unless it was moved into place.
class TemporaryFolder {
 public:
  explicit TemporaryFolder(const fs::path& site) {
    const fs::path parent = site.parent_path().empty() ? fs::path(".") : site.parent_path();
    // Hidden, so a listing of the parent does not show it as a site (appended piecewise: GCC 12 warns
    // falsely about "." + std::string).
    std::string leaf(".");
    leaf.append(site.filename().string()).append(".tmp-XXXXXX");
    std::string pattern = (parent / leaf).string();
    if (!::mkdtemp(pattern.data())) throw std::runtime_error(site.string() + ": cannot create a temporary folder beside it: " + std::strerror(errno));
    path_ = pattern;
  }
  ~TemporaryFolder() {
    std::error_code ec;
    if (!path_.empty()) fs::remove_all(path_, ec);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const fs::path& path() const { return path_; }
  void release() { path_.clear(); }

 private:
  fs::path path_;
};

void copyInto(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
  if (ec) throw std::runtime_error(to.string() + ": cannot copy " + from.string() + ": " + ec.message());
  // Readable by all, as a site is meant to be, whatever the source's mode was.
  fs::permissions(to, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read, ec);
}

// Puts the finished folder `built` at `site`: a plain rename when there is none yet; else the two are
// exchanged in one step (renameat2) and the old site, now at `built`, removed.
void swapIntoPlace(TemporaryFolder& built, const fs::path& site) {
  std::error_code ec;
  if (!fs::exists(site, ec)) {
    fs::rename(built.path(), site, ec);
    if (ec) throw std::runtime_error(site.string() + ": cannot move the site into place: " + ec.message());
    built.release();
    return;
  }
  if (::renameat2(AT_FDCWD, built.path().c_str(), AT_FDCWD, site.c_str(), RENAME_EXCHANGE) == 0) return;  // old site removed with `built`
  // A file system without exchange: move the old site aside, the new one in, then drop the old.
  const fs::path aside = fs::path(built.path().string() + "-old");
  fs::rename(site, aside, ec);
  if (ec) throw std::runtime_error(site.string() + ": cannot replace the old site: " + ec.message());
  fs::rename(built.path(), site, ec);
  if (ec) {
    std::error_code back;
    fs::rename(aside, site, back);
    throw std::runtime_error(site.string() + ": cannot move the site into place: " + ec.message());
  }
  built.release();
  fs::remove_all(aside, ec);
}

}  // namespace

bool isReplaceableSite(const fs::path& folder) {
  std::error_code ec;
  if (fs::is_empty(folder, ec) && !ec) return true;
  std::ifstream in(folder / layout::kIndex, std::ios::binary);
  if (!in) return false;
  std::string head(4096, '\0');
  in.read(head.data(), std::streamsize(head.size()));
  head.resize(size_t(in.gcount()));
  return head.find(std::string("<meta name=\"generator\" content=\"") + layout::kGenerator + "\">") != std::string::npos;
}

ReportResult writeReport(const ReportOptions& options) {
  // Everything is checked before anything is written.
  std::error_code ec;
  if (options.site.empty()) throw InputError("-o: an empty path");
  ReportOptions o = options;
  // "site/", "." and ".." name the folder itself; the temporary goes beside it.
  o.site = fs::absolute(o.site).lexically_normal();
  if (!o.site.has_filename()) o.site = o.site.parent_path();
  if (o.site == o.site.root_path()) throw InputError("-o " + options.site.string() + ": not a folder the site can replace");
  if (fs::exists(o.site, ec) && !fs::is_directory(o.site, ec))
    throw InputError("-o " + options.site.string() + ": is a file, not a folder for the site");
  if (fs::is_directory(o.site, ec) && !isReplaceableSite(o.site))
    throw InputError("-o " + options.site.string() + ": a folder that is neither empty nor a glossy report; not replacing it");

  std::vector<SheetRecord> sheets = readSheetFolder(o.sheetsDir);
  std::map<std::string, PlotIndex> plots;
  if (o.plotsDir) {
    if (!fs::is_directory(*o.plotsDir, ec)) throw InputError(o.plotsDir->string() + ": no such folder (PLOTS_DIR)");
    for (const SheetRecord& s : sheets)
      if (fs::is_regular_file(*o.plotsDir / s.name / "plots.json", ec)) {
        PlotIndex index = readPlotIndex(*o.plotsDir / s.name);
        if (!o.plotKinds.empty())
          std::erase_if(index.figures, [&](const PlotFigure& f) {
            return std::find(o.plotKinds.begin(), o.plotKinds.end(), f.kind) == o.plotKinds.end();
          });
        if (!o.plotData)
          for (PlotFigure& f : index.figures) {
            f.csv.clear();
            if (!f.png.empty()) f.svg.clear();
          }
        plots.emplace(s.name, std::move(index));
      }
  }

  fs::path parent = o.site.parent_path();
  if (!parent.empty()) {
    fs::create_directories(parent, ec);
    if (ec) throw InputError("-o " + options.site.string() + ": cannot create " + parent.string() + ": " + ec.message());
  }
  TemporaryFolder tmp(o.site);
  ReportResult result;
  result.materials = sheets.size();
  fs::create_directories(tmp.path() / "assets");
  writeFileAtomically(tmp.path() / layout::kStyle, siteStyleSheet());
  writeFileAtomically(tmp.path() / layout::kScript, siteScript());
  writeFileAtomically(tmp.path() / layout::kIndex, indexPage(sheets));
  for (size_t k = 0; k < sheets.size(); ++k) {
    const SheetRecord& s = sheets[k];
    const fs::path folder = tmp.path() / layout::materialFolder(s.name);
    fs::create_directories(folder);
    copyInto(s.png, folder / layout::sheetImage());
    ++result.images;
    std::vector<const PanelRecord*> shown;
    for (const PanelRecord& p : s.panels)
      if (!p.empty) shown.push_back(&p);
    writePanelPngs(s.exr, shown, s.pngExposure, [&](const PanelRecord& p) { return folder / layout::panelImage(p.layer); });
    result.images += shown.size();
    const auto it = plots.find(s.name);
    if (it != plots.end() && !it->second.figures.empty()) {
      fs::create_directories(folder / "plots");
      for (const PlotFigure& f : it->second.figures)
        for (const std::string* file : {&f.png, &f.svg, &f.csv})
          if (!file->empty() && !fs::exists(folder / layout::plotFile(*file), ec)) {
            copyInto(it->second.folder / *file, folder / layout::plotFile(*file));
            ++result.plots;
          }
    }
    writeFileAtomically(folder / "index.html", materialPage(s, it == plots.end() ? nullptr : &it->second, k ? &sheets[k - 1] : nullptr,
                                                            k + 1 < sheets.size() ? &sheets[k + 1] : nullptr));
  }
  // mkdtemp makes the folder private (0700); a site is for reading.
  fs::permissions(tmp.path(), fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec | fs::perms::others_read |
                                  fs::perms::others_exec, ec);
  swapIntoPlace(tmp, o.site);
  return result;
}

}  // namespace glossy::report
