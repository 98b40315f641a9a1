// Reading a sheet's figures from its EXR header (sheet_record.h).
#include "renderer/report/sheet_record.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "materials/params/material_name.h"
#include "renderer/sheet/sheet.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace glossy::report {

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
  // "lo hi"; nullopt unless both are finite numbers.
  std::optional<std::pair<double, double>> interval(const std::string& name) const {
    std::istringstream in(text(name));
    std::string a, b, rest;
    if (!(in >> a >> b) || (in >> rest)) return std::nullopt;
    const auto lo = parseNumber(a), hi = parseNumber(b);
    if (!lo || !hi || !std::isfinite(*lo) || !std::isfinite(*hi)) return std::nullopt;
    return std::pair{*lo, *hi};
  }
  Figure figure(const std::string& name) const {
    Figure f;
    f.value = number(name);
    if (const auto ci = interval(name + "Ci")) {
      f.lo = ci->first;
      f.hi = ci->second;
    }
    return f;
  }
  [[noreturn]] void fail(const std::string& why) const { throw InputError(path_.string() + ": " + why); }

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

SheetRecord readSheetRecord(const std::filesystem::path& exr) {
  SheetRecord r;
  r.name = exr.stem().string();
  r.exr = exr;
  checkMaterialName(r.name, exr.string());
  auto in = OIIO::ImageInput::open(exr.string());
  if (!in) throw InputError(exr.string() + ": cannot read: " + printableLine(OIIO::geterror()));
  const OIIO::ImageSpec spec = in->spec();
  in->close();
  const Header h(exr, spec);
  const std::string names = h.text("glossy:panels");
  if (names.empty()) h.fail("not a glossy sheet (no glossy:panels)");
  r.materialFile = h.text("glossy:material");
  r.measured = h.text("glossy:measured");
  r.verdict = h.text("glossy:verdict");
  r.env = h.text("glossy:env");
  r.scene = h.text("glossy:scene");
  r.spp = h.text("glossy:spp");
  r.pngExposure = h.number("glossy:pngExposure").value_or(0.0);
  if (std::abs(r.pngExposure) > 64.0) h.fail("glossy:pngExposure out of range");
  r.flipNoiseFloor = h.number("glossy:flipNoiseFloor");

  for (const std::string& layer : split(names, ',')) {
    if (!isMaterialName(layer)) h.fail("panel '" + shortened(layer) + "' in glossy:panels is not a plain name");
    if (r.panel(layer)) h.fail("panel '" + layer + "' is listed twice");
    PanelRecord p;
    p.layer = layer;
    const std::string key = "glossy:panel." + layer, error = "glossy:error." + layer;
    std::istringstream box(h.text(key + ".box"));
    std::string rest;
    if (!(box >> p.x >> p.y >> p.width >> p.height) || (box >> rest) || p.x < 0 || p.y < 0 || p.width <= 0 ||
        p.height <= 0 || p.x + p.width > spec.width || p.y + p.height > spec.height)
      h.fail("panel '" + layer + "' has no box inside the image");
    const int first = spec.channelindex(layer + ".R");
    if (first < 0 || spec.channelindex(layer + ".G") < 0 || spec.channelindex(layer + ".B") < 0)
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
    p.relativeRmse = h.figure(error + ".relativeRmse");
    p.luminanceRatio = h.figure(error + ".luminanceRatio");
    p.flip = h.figure(error + ".flip");
    p.relativeRmseNoisy = h.number(error + ".relativeRmseNoisy");
    p.e1 = h.number(error + ".E1");
    p.e2 = h.number(error + ".E2");
    p.noiseFree = h.text(error + ".noiseFree");
    r.panels.push_back(std::move(p));
  }

  r.png = std::filesystem::path(exr).replace_extension(".png");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(r.png, ec)) throw InputError(r.png.string() + ": missing (the sheet's PNG beside " + exr.filename().string() + ")");
  auto png = OIIO::ImageInput::open(r.png.string());
  if (!png || png->format_name() != std::string("png")) throw InputError(r.png.string() + ": not a readable PNG");
  return r;
}

std::vector<SheetRecord> readSheetFolder(const std::filesystem::path& folder) {
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) throw InputError(folder.string() + ": no such folder (SHEETS_DIR)");
  std::vector<std::filesystem::path> exrs;
  for (const auto& e : std::filesystem::directory_iterator(folder, ec))
    if (e.path().extension() == ".exr" && !e.path().filename().string().starts_with(".") && e.is_regular_file(ec))
      exrs.push_back(e.path());
  if (ec) throw InputError(folder.string() + ": cannot list: " + ec.message());
  if (exrs.empty()) throw InputError(folder.string() + ": holds no sheets (NAME.exr from glossy sheets)");
  std::sort(exrs.begin(), exrs.end());
  std::vector<SheetRecord> records;
  for (const auto& exr : exrs) records.push_back(readSheetRecord(exr));
  return records;
}

}  // namespace glossy::report
