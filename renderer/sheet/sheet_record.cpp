// Reading a sheet's figures from its EXR header (sheet_record.h).
#include "renderer/sheet/sheet_record.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/params/material_name.h"
#include "renderer/image/image_input.h"
#include "renderer/output/input_folder.h"
#include "renderer/sheet/comparison_grid.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <sstream>

namespace glossy {

namespace {

class Header {
 public:
  Header(const std::filesystem::path& path, const OIIO::ImageSpec& spec) : path_(path), spec_(spec) {}

  std::string text(const std::string& name) const {
    const OIIO::ParamValue* p = spec_.find_attribute(name);
    return p ? printableLine(p->get_string(), 2000) : std::string();
  }
  // A finite number, stored as a number or as text; absent (or NaN/Inf) gives nullopt.
  std::optional<double> number(const std::string& name) const {
    const OIIO::ParamValue* p = spec_.find_attribute(name);
    if (!p) return std::nullopt;
    std::optional<double> v;
    if (p->type() == OIIO::TypeDesc::STRING)
      v = parseNumber(p->get_string());
    else if (p->type() == OIIO::TypeDesc::INT)
      v = p->get_int();  // get_float gives 0 for an int attribute
    else if (p->type() == OIIO::TypeDesc::FLOAT || p->type() == OIIO::TypeDesc::HALF || p->type() == OIIO::TypeDesc::DOUBLE)
      v = p->get_float();
    if (v && !std::isfinite(*v)) v.reset();
    return v;
  }
  // Text of several lines, each made printable; no lines when absent.
  std::vector<std::string> lines(const std::string& name) const {
    std::vector<std::string> out;
    const OIIO::ParamValue* p = spec_.find_attribute(name);
    if (!p) return out;
    std::istringstream in(p->get_string());
    for (std::string line; std::getline(in, line) && out.size() < 100;)
      if (const std::string l = printableLine(line, 2000); !l.empty()) out.push_back(l);
    return out;
  }
  // "lo hi"; nullopt unless both are finite numbers.
  std::optional<std::pair<double, double>> interval(const std::string& name) const {
    std::istringstream in(text(name));
    std::string a, b, rest;
    if (!(in >> a >> b) || (in >> rest)) return std::nullopt;
    const auto lo = parseNumber(a), hi = parseNumber(b);
    if (!lo || !hi || !std::isfinite(*lo) || !std::isfinite(*hi)) return std::nullopt;
    return std::pair{*lo, *hi};
  }
  // A number that must lie in [lo, hi] (what the figure can be: an RMSE is never negative, ꟻLIP never
  // above 1): a crafted or corrupt sheet is refused, not analysed as if its figure were real.
  std::optional<double> bounded(const std::string& name, double lo, double hi) const {
    const std::optional<double> v = number(name);
    if (v && !(*v >= lo && *v <= hi)) fail(formatted("%s = %g is outside its domain %s", name.c_str(), *v, domain(lo, hi).c_str()));
    return v;
  }
  // A figure in [lo, hi]; its interval must be ordered, and reach into the domain (`intervalLo` is how far
  // below it the interval may start: a luminance ratio's normal interval may begin below 0).
  Figure figure(const std::string& name, double lo, double hi, double intervalLo) const {
    Figure f;
    f.value = bounded(name, lo, hi);
    if (const auto ci = interval(name + "Ci")) {
      if (!(ci->first <= ci->second))
        fail(formatted("%sCi = %g %g is a reversed interval (its low end above its high end)", name.c_str(), ci->first, ci->second));
      if (!(ci->first >= intervalLo && ci->second >= lo && ci->second <= hi))
        fail(formatted("%sCi = %g %g is outside its domain %s", name.c_str(), ci->first, ci->second, domain(intervalLo, hi).c_str()));
      f.lo = ci->first;
      f.hi = ci->second;
    }
    return f;
  }
  ImageFigures figures(const std::string& prefix) const {
    const double inf = std::numeric_limits<double>::infinity();
    return {figure(prefix + ".relativeRmse", 0.0, inf, 0.0), figure(prefix + ".luminanceRatio", 0.0, inf, -inf),
            figure(prefix + ".flip", 0.0, 1.0, 0.0), figure(prefix + ".deltaEItp", 0.0, inf, 0.0),
            figure(prefix + ".ssim", -1.0, 1.0, -1.0), bounded(prefix + ".relativeRmseNoisy", 0.0, inf)};
  }
  [[noreturn]] void fail(const std::string& why) const { throw InputError(path_.string() + ": " + why); }

  static std::string domain(double lo, double hi) {
    const auto end = [](double v) { return std::isinf(v) ? std::string(v < 0 ? "-inf" : "inf") : formatted("%g", v); };
    return formatted("[%s, %s]", end(lo).c_str(), end(hi).c_str());
  }

 private:
  std::filesystem::path path_;
  const OIIO::ImageSpec& spec_;
};

std::vector<std::string> split(const std::string& text, char sep) {
  std::vector<std::string> items;
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, sep)) {
    item.erase(0, item.find_first_not_of(' '));
    item.erase(item.find_last_not_of(' ') + 1);
    items.push_back(item);
  }
  return items;
}

}  // namespace

const PanelRecord* SheetRecord::panel(const std::string& layer) const {
  for (const PanelRecord& p : panels)
    if (p.layer == layer) return &p;
  return nullptr;
}

const PanelRecord* SheetRecord::measuredPanel() const {
  for (const PanelRecord& p : panels)
    if (p.isMeasured()) return &p;
  return nullptr;
}

std::vector<std::string> SheetRecord::closestLayers() const {
  std::string names;
  if (verdict.starts_with("closest: "))
    names = verdict.substr(9);
  else if (verdict.starts_with("tie: "))
    names = verdict.substr(5);
  std::vector<std::string> layers;
  for (const std::string& label : split(names, ','))
    for (const PanelRecord& p : panels)
      if (!p.isMeasured() && p.label == label) layers.push_back(p.layer);
  return layers;
}

bool SheetRecord::isTie() const { return verdict.starts_with("tie: ") && closestLayers().size() > 1; }

namespace {

// What the report handles, so a header cannot make it allocate without bound: the panel count, the image's
// side, and the pixels of the sheet's PNG it decodes (3 bytes each).
constexpr int64_t kMaxPanels = 256;
constexpr int64_t kMaxSide = int64_t(1) << 24;
constexpr int64_t kMaxPngPixels = int64_t(1) << 30;

// A whole number in 64 bits; nullopt for anything else (a sign, a fraction, digits beyond int64).
std::optional<int64_t> wholeNumber(const std::string& text) {
  int64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
  return v;
}

// "x y width height", each a whole number, the box inside a width × height image.
std::optional<std::array<int64_t, 4>> panelBox(const std::string& text, int64_t width, int64_t height) {
  std::istringstream in(text);
  std::array<int64_t, 4> box{};
  std::string word;
  for (int64_t& v : box) {
    if (!(in >> word)) return std::nullopt;
    const auto n = wholeNumber(word);
    if (!n) return std::nullopt;
    v = *n;
  }
  if (in >> word) return std::nullopt;
  const auto [x, y, w, h] = box;
  // Each term is checked before the sums, which then cannot overflow.
  if (x < 0 || y < 0 || w <= 0 || h <= 0 || x > width || y > height || w > width - x || h > height - y) return std::nullopt;
  return box;
}

// An attribute as text, whatever type it was stored as.
std::string attributeText(const OIIO::ImageSpec& spec, const std::string& name) {
  const OIIO::ParamValue* p = spec.find_attribute(name);
  if (!p) return "";
  if (p->type() == OIIO::TypeDesc::STRING) return printableLine(p->get_string(), 2000);
  if (p->type() == OIIO::TypeDesc::INT) return std::to_string(p->get_int());
  return formatted("%g", double(p->get_float()));
}

// The settings the report compares, in the order it shows them: glossy:settings ("key=value; ..."), or for
// a sheet from before it, the attributes of the same meaning.
std::vector<SheetSetting> sheetSettings(const OIIO::ImageSpec& spec) {
  struct Known {
    const char* key;
    const char* label;
    const char* attribute;  // the older sheet's attribute
  };
  static constexpr Known kKnown[] = {
      {"scene", "scene", "glossy:scene"},
      {"env", "lighting", "glossy:env"},
      {"size", "panel size", "glossy:panelSize"},
      {"spp", "samples per pixel", "glossy:spp"},
      {"time", "seconds per panel", "glossy:secondsPerPanel"},
      {"targetError", "target error", "glossy:targetError"},
      {"seed", "seed", "glossy:seed"},
      {"maxDepth", "path segments at most", "glossy:maxDepth"},
      {"lightSamples", "light samples", "glossy:lightSamples"},
      {"format", "sheet format", nullptr},
  };
  std::map<std::string, std::string> line;
  const OIIO::ParamValue* p = spec.find_attribute("glossy:settings");
  const bool hasLine = p && p->type() == OIIO::TypeDesc::STRING;
  if (hasLine)
    for (const std::string& item : split(printableLine(p->get_string(), 8000), ';'))
      if (const size_t eq = item.find('='); eq != std::string::npos) line[item.substr(0, eq)] = item.substr(eq + 1);
  std::vector<SheetSetting> settings;
  for (const Known& k : kKnown) {
    std::string value = hasLine ? line[k.key] : k.attribute ? attributeText(spec, k.attribute) : std::string("1");
    if (std::string(k.key) == "scene" || std::string(k.key) == "env") value = withoutFolders(value);
    settings.push_back({k.key, k.label, value.empty() ? "unknown" : value});
  }
  return settings;
}

// The material's name from the sheet, not its file name (which a user may have chosen): it names the
// material's page, so it must be a usable material name.
std::string materialName(const Header& h, const std::filesystem::path& exr) {
  if (const std::string name = h.text("glossy:materialName"); !name.empty()) {
    checkMaterialName(name, exr.string() + ": glossy:materialName");
    return name;
  } else if (const std::string file = h.text("glossy:material"); !file.empty()) {
    const std::string stem = std::filesystem::path(file).stem().string();
    checkMaterialName(stem, exr.string() + ": glossy:material");
    return stem;
  }
  h.fail("not a glossy sheet (no glossy:materialName or glossy:material)");
}

// Panel `layer`'s record from the header: its box inside the image (with its R, G, B channels), label, fit,
// note, parameters, colour and figures.
PanelRecord readPanel(const Header& h, const OIIO::ImageSpec& spec, const std::string& layer) {
  const std::string key = "glossy:panel." + layer, error = "glossy:error." + layer;
  PanelRecord p;
  static_cast<ImageFigures&>(p) = h.figures(error);
  p.layer = layer;
  const auto box = panelBox(h.text(key + ".box"), spec.width, spec.height);
  if (!box) h.fail("panel '" + layer + "' has no box inside the image");
  p.x = int((*box)[0]);
  p.y = int((*box)[1]);
  p.width = int((*box)[2]);
  p.height = int((*box)[3]);
  if (spec.channelindex(layer + ".R") < 0 || spec.channelindex(layer + ".G") < 0 || spec.channelindex(layer + ".B") < 0)
    h.fail("panel '" + layer + "' has no layer " + layer + ".R/G/B");
  p.label = h.text(key + ".label");
  if (p.label.empty()) p.label = layer;
  p.fit = h.text(key + ".fit");
  p.note = h.text(key + ".note");
  p.params = h.text(key + ".params");
  p.colour = h.text(key + ".colour");
  if (!(p.colour.size() == 7 && p.colour[0] == '#' &&
        std::all_of(p.colour.begin() + 1, p.colour.end(), [](char c) { return std::isxdigit((unsigned char)c); })))
    p.colour.clear();
  if (p.colour.empty())  // a sheet that does not say: the grid's own colour for the panel, as plots use it
    for (const SheetPanel& known : sheetPanels())
      if (known.layer == layer && !known.fit.empty()) p.colour = known.colour;
  p.empty = h.number(key + ".empty").value_or(0.0) != 0.0;
  p.e1 = h.bounded(error + ".E1", 0.0, std::numeric_limits<double>::infinity());
  p.e2 = h.bounded(error + ".E2", 0.0, std::numeric_limits<double>::infinity());
  p.noiseFree = h.text(error + ".noiseFree");
  return p;
}

// The PNG beside the sheet, drawn with it: the site's images are cut from it, so it must be the EXR's width
// (the panels' boxes are the same in both) and reach below the panels.
void readPng(const std::filesystem::path& folder, SheetRecord& r, int exrWidth) {
  const std::filesystem::path& exr = r.exr;
  r.png = std::filesystem::path(exr).replace_extension(".png");
  checkInputFile(folder, r.png, "sheet's PNG beside " + exr.filename().string());
  auto png = openImageFile(r.png, "PNG");
  const OIIO::ImageSpec& ps = png->spec();
  if (ps.width != exrWidth || ps.height < r.panelsBottom || int64_t(ps.width) * int64_t(ps.height) > kMaxPngPixels)
    throw InputError(r.png.string() + formatted(": %d x %d pixels, not the PNG of %s (%d wide, its panels %d high)", ps.width, ps.height,
                                                exr.filename().string().c_str(), exrWidth, r.panelsBottom));
  r.pngHeight = ps.height;
}

}  // namespace

SheetRecord readSheetRecord(const std::filesystem::path& folder, const std::filesystem::path& exr) {
  SheetRecord r;
  r.exr = exr;
  checkInputFile(folder, exr, "sheet");
  auto in = openImageFile(exr, "sheet");
  const OIIO::ImageSpec spec = in->spec();
  in->close();
  const Header h(exr, spec);
  const std::string names = h.text("glossy:panels");
  if (names.empty()) h.fail("not a glossy sheet (no glossy:panels)");
  if (spec.width <= 0 || spec.height <= 0 || spec.width > kMaxSide || spec.height > kMaxSide)
    h.fail(formatted("%d x %d pixels, not a sheet the report handles (at most %lld a side)", spec.width, spec.height, (long long)kMaxSide));
  r.imageWidth = spec.width;
  r.imageHeight = spec.height;

  r.name = materialName(h, exr);
  r.materialFile = h.text("glossy:material");
  r.measured = h.text("glossy:measured");
  r.verdict = h.text("glossy:verdict");
  r.env = h.text("glossy:env");
  r.scene = h.text("glossy:scene");
  r.spp = h.text("glossy:spp");
  r.pngExposure = h.number("glossy:pngExposure").value_or(0.0);
  if (std::abs(r.pngExposure) > 64.0) h.fail("glossy:pngExposure out of range");
  r.flipNoiseFloor = h.bounded("glossy:flipNoiseFloor", 0.0, 1.0);
  r.warnings = h.lines("glossy:warnings");
  if (h.number("glossy:noiseFloor.relativeRmseNoisy")) r.noiseFloor = h.figures("glossy:noiseFloor");
  r.settings = sheetSettings(spec);

  const std::vector<std::string> layers = split(names, ',');
  if (int64_t(layers.size()) > kMaxPanels) h.fail(formatted("%zu panels in glossy:panels, more than the report handles (%lld)", layers.size(), (long long)kMaxPanels));
  for (const std::string& layer : layers) {
    if (!isMaterialName(layer)) h.fail("panel '" + shortened(layer) + "' in glossy:panels is not a plain name");
    if (r.panel(layer)) h.fail("panel '" + layer + "' is listed twice");
    PanelRecord p = readPanel(h, spec, layer);
    r.panelsBottom = std::max(r.panelsBottom, p.y + p.height);  // <= spec.height: no overflow
    r.panels.push_back(std::move(p));
  }

  readPng(folder, r, spec.width);
  return r;
}

std::vector<SheetRecord> readSheetFolder(const std::filesystem::path& folder) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) throw InputError(folder.string() + ": no such folder (SHEETS_DIR)");
  std::vector<std::filesystem::path> exrs;
  for (const auto& e : std::filesystem::directory_iterator(folder, ec))
    if (e.path().extension() == ".exr" && !e.path().filename().string().starts_with(".")) exrs.push_back(e.path());
  if (ec) throw InputError(folder.string() + ": cannot list: " + ec.message());
  if (exrs.empty()) throw InputError(folder.string() + ": holds no sheets (NAME.exr from glossy sheets)");
  std::sort(exrs.begin(), exrs.end());
  std::vector<SheetRecord> records;
  std::map<std::string, std::filesystem::path> byName;
  for (const auto& exr : exrs) {
    records.push_back(readSheetRecord(folder, exr));
    const auto [it, fresh] = byName.emplace(records.back().name, exr);
    if (!fresh)
      throw InputError(exr.string() + ": a sheet of " + records.back().name + ", like " + it->second.filename().string() +
                       "; a report has one sheet per material");
  }
  std::sort(records.begin(), records.end(), [](const SheetRecord& a, const SheetRecord& b) { return a.name < b.name; });
  return records;
}

void checkSameSettings(const std::vector<SheetRecord>& sheets) {
  for (size_t k = 1; k < sheets.size(); ++k)
    for (size_t i = 0; i < sheets[0].settings.size() && i < sheets[k].settings.size(); ++i) {
      const SheetSetting &a = sheets[0].settings[i], &b = sheets[k].settings[i];
      if (a.value != b.value)
        throw InputError(sheets[0].exr.string() + " and " + sheets[k].exr.filename().string() + " were made with different settings (" +
                         a.label + " " + shortened(a.value) + " and " + shortened(b.value) +
                         "): one report compares sheets made alike; make a report per setting");
    }
}

}  // namespace glossy
