#include "renderer/app/merge_job.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/params/material_file.h"
#include "renderer/app/destination.h"
#include "renderer/output/inside_folder.h"
#include "renderer/sheet/sheet_record.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/notes.h"
#include "renderer/util/output_lock.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <map>
#include <optional>

namespace glossy::app {

namespace {

std::vector<std::filesystem::path> tomlFiles(const std::filesystem::path& dir) {
  if (std::error_code ec; !std::filesystem::is_directory(dir, ec)) throw InputError(dir.string() + ": not a directory");
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".toml") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) throw InputError(dir.string() + ": no parameter files (*.toml)");
  return files;
}

}  // namespace

// The rule of glossy fit -o (fit_output.h), for fits that come from files: glossy's fit replaces glossy's
// earlier one of the same model and metric, saying so; a published fit is added where the library has
// none, and never replaces a different published one unless --replace. Two files naming one material are
// refused: which of them should win is the user's to say.
MergeFitsResult mergeFits(const MergeFitsRequest& o) {
  checkOutputFolder(o.library, o.libraryName);
  const OutputLock lock(o.library, o.libraryName);
  // Everything read and checked first: a bad file anywhere fails the merge before a file is written.
  struct Merged {
    MaterialFile material;
    std::filesystem::path from;  // the shard file
    bool changed = false;
  };
  std::map<std::string, Merged> merged;  // by material name
  std::vector<std::string> replacedLines;
  size_t fits = 0, unchanged = 0;
  for (const auto& path : tomlFiles(o.fitsDir)) {
    const MaterialFile shard = loadMaterialFile(path);
    if (auto seen = merged.find(shard.name); seen != merged.end())
      throw InputError(path.string() + ": names the material '" + shard.name + "', as " + seen->second.from.string() +
                       " does: merge one of them at a time");
    const std::filesystem::path into = std::filesystem::path(o.library) / (shard.name + ".toml");
    checkWriteInside(o.library, into, o.libraryName);
    std::error_code ec;
    const bool exists = std::filesystem::exists(into, ec);
    MaterialFile library = exists ? loadMaterialFile(into) : shard;
    if (library.name != shard.name)
      throw InputError(into.string() + ": names the material '" + library.name + "', not '" + shard.name + "' of " + path.string());
    if (!exists) library.fits.clear();
    Merged& m = merged.emplace(shard.name, Merged{std::move(library), path, !exists}).first->second;
    for (const Fit& f : shard.fits) {
      ++fits;
      const Fit* there = m.material.findExact(f.id);
      if (there && *there == f) {
        ++unchanged;
        continue;
      }
      if (there && !f.id.isGlossys() && !o.replace)
        throw InputError(into.string() + ": its published " + f.id.str() + " fit differs from the one in " + path.string() +
                         " (glossy merge never replaces a published fit; --replace does)");
      if (there)
        replacedLines.push_back(into.string() + ": " + (f.id.isGlossys() ? "glossy's " : "the published ") + f.id.str() +
                                " fit replaced by " + path.string() + "'s" + (f.date.empty() ? "" : " of " + f.date) +
                                (there->date.empty() ? "" : " (it was of " + there->date + ")"));
      m.material.put(f);
      m.changed = true;
    }
  }
  std::filesystem::create_directories(o.library);
  size_t written = 0;
  for (const auto& [name, m] : merged)
    if (m.changed) writeFileAtomically(std::filesystem::path(o.library) / (name + ".toml"), toToml(m.material)), ++written;
  for (const std::string& line : replacedLines) tell("glossy merge: " + line);
  tell(formatted("glossy merge: %zu fits of %zu materials into %s (%zu replacing fits there, %zu already there; %zu files written)", fits,
                 merged.size(), o.library.c_str(), replacedLines.size(), unchanged, written));
  return {fits, merged.size(), replacedLines.size(), unchanged, written};
}

namespace {

std::string number(const std::optional<double>& v) {
  if (!v) return "";
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, *v);
  return std::string(buf, end);
}

nlohmann::json jsonNumber(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); }

// An image's figures, a panel's or the noise floor's: as CSV cells (relative_rmse … relative_rmse_noisy) and
// as JSON members.
std::string figureCells(const ImageFigures& f) {
  std::string cells;
  for (const Figure* g : {&f.relativeRmse, &f.luminanceRatio, &f.flip, &f.deltaEItp, &f.ssim})
    cells += number(g->value) + "," + number(g->lo) + "," + number(g->hi) + ",";
  return cells + number(f.relativeRmseNoisy);
}

nlohmann::json figureJson(const ImageFigures& f) {
  const auto ci = [](const Figure& g) { return g.lo ? nlohmann::json{*g.lo, *g.hi} : nlohmann::json(nullptr); };
  return {{"relative_rmse", jsonNumber(f.relativeRmse.value)}, {"relative_rmse_ci", ci(f.relativeRmse)},
          {"luminance_ratio", jsonNumber(f.luminanceRatio.value)}, {"luminance_ratio_ci", ci(f.luminanceRatio)},
          {"flip", jsonNumber(f.flip.value)}, {"flip_ci", ci(f.flip)}, {"delta_e_itp", jsonNumber(f.deltaEItp.value)},
          {"delta_e_itp_ci", ci(f.deltaEItp)}, {"ssim", jsonNumber(f.ssim.value)}, {"ssim_ci", ci(f.ssim)},
          {"relative_rmse_noisy", jsonNumber(f.relativeRmseNoisy)}};
}

}  // namespace

MergeSheetsResult mergeSheets(const MergeSheetsRequest& o) {
  if (o.csv.empty() && o.json.empty()) throw InputError("glossy merge sheets needs " + o.csvName + " FILE, " + o.jsonName + " FILE or both");
  if (!o.csv.empty()) checkOutputFile(o.csv, o.csvName, {".csv"}, Folder::Create);
  if (!o.json.empty()) checkOutputFile(o.json, o.jsonName, {".json"}, Folder::Create);
  std::optional<OutputLock> csvLock, jsonLock;
  if (!o.csv.empty()) csvLock.emplace(o.csv, o.csvName);
  if (!o.json.empty()) jsonLock.emplace(o.json, o.jsonName);
  const std::vector<SheetRecord> sheets = readSheetFolder(o.sheetsDir);

  std::string csv =
      "material,panel,label,fit,empty,spp,relative_rmse,relative_rmse_lo,relative_rmse_hi,luminance_ratio,luminance_ratio_lo,"
      "luminance_ratio_hi,flip,flip_lo,flip_hi,delta_e_itp,delta_e_itp_lo,delta_e_itp_hi,ssim,ssim_lo,ssim_hi,relative_rmse_noisy,E1,E2,"
      "closest,verdict,warning\n";
  nlohmann::json doc = {{"sheets", nlohmann::json::array()}};
  for (const SheetRecord& s : sheets) {
    const std::vector<std::string> closest = s.closestLayers();
    const std::string warning = joined(s.warnings, "; ");  // the sheet's warnings on one line
    nlohmann::json panels = nlohmann::json::array();
    for (const PanelRecord& p : s.panels) {
      const bool isClosest = std::find(closest.begin(), closest.end(), p.layer) != closest.end();
      csv += csvField(s.name) + "," + p.layer + "," + csvField(p.label) + "," + csvField(p.fit) + "," + (p.empty ? "1" : "0") + "," +
             csvField(s.spp) + "," + figureCells(p) + "," + number(p.e1) + "," + number(p.e2) + "," + (isClosest ? "1" : "0") + "," +
             csvField(s.verdict) + "," + csvField(warning) + "\n";
      nlohmann::json panel = figureJson(p);  // a std::map: its members come out sorted, wherever they were put
      panel.update({{"panel", p.layer}, {"label", p.label}, {"fit", p.fit}, {"empty", p.empty},
                    {"E1", jsonNumber(p.e1)}, {"E2", jsonNumber(p.e2)}, {"closest", isClosest}});
      panels.push_back(std::move(panel));
    }
    // The noise-floor row: the measured panel against an independent render of itself (docs/sheets.md).
    nlohmann::json floor = nullptr;
    if (const auto& f = s.noiseFloor) {
      csv += csvField(s.name) + ",noise_floor,noise floor,measured,0," + csvField(s.spp) + "," + figureCells(*f) + ",0,0,0," +
             csvField(s.verdict) + "," + csvField(warning) + "\n";
      floor = figureJson(*f);
    }
    doc["sheets"].push_back({{"material", s.name}, {"verdict", s.verdict}, {"warnings", s.warnings}, {"measured", s.measured},
                             {"spp", s.spp}, {"scene", s.scene}, {"env", s.env}, {"panels", std::move(panels)},
                             {"noise_floor", std::move(floor)}});
  }
  for (const auto& [path, text] : {std::pair{o.csv, csv}, std::pair{o.json, doc.dump(1) + "\n"}}) {
    if (path.empty()) continue;
    if (const std::filesystem::path p = path; p.has_parent_path()) std::filesystem::create_directories(p.parent_path());
    writeFileAtomically(path, text);
  }
  tell("glossy merge: the figures of " + std::to_string(sheets.size()) + " sheets from " + o.sheetsDir);
  return {sheets.size()};
}

}  // namespace glossy::app
