#include "renderer/study/study_tables.h"

#include "materials/core/text.h"

#include <charconv>
#include <cmath>
#include <optional>
#include <vector>

namespace glossy::study {

namespace {

using Json = nlohmann::ordered_json;
using Opt = std::optional<double>;

// The shortest text that reads back as `v`: a float32 figure's (the sheets store figures as float32) as
// float, so that 0.1f is "0.1" rather than its double expansion "0.10000000149011612"; any other as double.
std::string shortest(double v) {
  char buffer[64];
  const float f = static_cast<float>(v);
  const auto [end, ec] = std::isfinite(v) && static_cast<double>(f) == v ? std::to_chars(buffer, buffer + sizeof buffer, f)
                                                                          : std::to_chars(buffer, buffer + sizeof buffer, v);
  return ec == std::errc() ? std::string(buffer, end) : formatted("%.17g", v);
}

// A figure as the files hold it: the double its shortest text reads as, which JSON then prints as that text.
Json num(const Opt& v) {
  if (!v) return Json(nullptr);
  const std::string text = shortest(*v);
  double d = *v;
  std::from_chars(text.data(), text.data() + text.size(), d);
  return Json(d);
}

// A row's fields in the files' order, declared once: the CSV's column, the JSON's key, the value.
struct Column {
  const char* csv;
  const char* json;
  Json (*value)(const StudyRow&);
};

const Column kColumns[] = {
    {"material", "material", [](const StudyRow& r) { return Json(r.material); }},
    {"database", "database", [](const StudyRow& r) { return Json(r.database); }},
    {"material_class", "materialClass", [](const StudyRow& r) { return Json(r.materialClass); }},
    {"lighting", "lighting", [](const StudyRow& r) { return Json(r.lighting); }},
    {"scene", "scene", [](const StudyRow& r) { return Json(r.scene); }},
    {"layer", "layer", [](const StudyRow& r) { return Json(r.layer); }},
    {"label", "label", [](const StudyRow& r) { return Json(r.label); }},
    {"fit", "fit", [](const StudyRow& r) { return Json(r.fit); }},
    {"fit_metric", "fitMetric", [](const StudyRow& r) { return Json(r.fitMetric); }},
    {"fit_source", "fitSource", [](const StudyRow& r) { return Json(r.fitSource); }},
    {"e1", "e1", [](const StudyRow& r) { return num(r.e1); }},
    {"e2", "e2", [](const StudyRow& r) { return num(r.e2); }},
    {"rrmse", "rrmse", [](const StudyRow& r) { return num(r.rrmse); }},
    {"rrmse_lo", "rrmseLo", [](const StudyRow& r) { return num(r.rrmseLo); }},
    {"rrmse_hi", "rrmseHi", [](const StudyRow& r) { return num(r.rrmseHi); }},
    {"rrmse_clamped", "rrmseClamped", [](const StudyRow& r) { return Json(r.rrmseClamped); }},
    {"flip", "flip", [](const StudyRow& r) { return num(r.flip); }},
    {"flip_lo", "flipLo", [](const StudyRow& r) { return num(r.flipLo); }},
    {"flip_hi", "flipHi", [](const StudyRow& r) { return num(r.flipHi); }},
    {"delta_e_itp", "deltaEItp", [](const StudyRow& r) { return num(r.deltaEItp); }},
    {"delta_e_itp_lo", "deltaEItpLo", [](const StudyRow& r) { return num(r.deltaEItpLo); }},
    {"delta_e_itp_hi", "deltaEItpHi", [](const StudyRow& r) { return num(r.deltaEItpHi); }},
    {"ssim", "ssim", [](const StudyRow& r) { return num(r.ssim); }},
    {"ssim_lo", "ssimLo", [](const StudyRow& r) { return num(r.ssimLo); }},
    {"ssim_hi", "ssimHi", [](const StudyRow& r) { return num(r.ssimHi); }},
    {"luminance_ratio", "luminanceRatio", [](const StudyRow& r) { return num(r.luminanceRatio); }},
    {"closest", "closest", [](const StudyRow& r) { return Json(r.closest); }},
    {"tied", "tied", [](const StudyRow& r) { return Json(r.tied); }},
    {"warning", "warning", [](const StudyRow& r) { return Json(r.warning); }},
    {"sheet", "sheet", [](const StudyRow& r) { return Json(r.sheet); }},
    {"width", "width", [](const StudyRow& r) { return Json(r.width); }},
    {"height", "height", [](const StudyRow& r) { return Json(r.height); }},
    {"spp", "spp", [](const StudyRow& r) { return Json(r.spp); }},
    {"seed", "seed", [](const StudyRow& r) { return Json(r.seed); }},
};

// A value as its CSV field: a figure as its shortest text, absent as an empty field, a flag as 1 or 0.
std::string csvCell(const Json& v) {
  if (v.is_null()) return "";
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  if (v.is_number_float()) return shortest(v.get<double>());
  if (v.is_number()) return v.dump();
  return csvField(v.get<std::string>());
}

}  // namespace

std::string rowsCsv(std::span<const StudyRow> rows) {
  std::string out = joined(kColumns, ",", [](const Column& c) { return c.csv; }) + "\n";
  for (const StudyRow& r : rows) {
    for (const Column& c : kColumns) out.append(&c == kColumns ? "" : ",").append(csvCell(c.value(r)));
    out += '\n';
  }
  return out;
}

nlohmann::ordered_json rowsJson(std::span<const StudyRow> rows) {
  Json out = Json::array();
  for (const StudyRow& r : rows) {
    Json j;
    for (const Column& c : kColumns) j[c.json] = c.value(r);
    out.push_back(std::move(j));
  }
  return out;
}

std::string latexEscape(const std::string& s) {
  static const std::pair<const char*, const char*> kKnown[] = {{"°", "\\textdegree{}"}, {"ö", "\\\"{o}"},     {"–", "--"},
                                                               {"×", "$\\times$"},     {"ρ", "$\\rho$"}, {"²", "$^2$"},
                                                               {"≥", "$\\geq$"}};
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    const char c = s[i];
    if (static_cast<unsigned char>(c) >= 0x80) {
      std::size_t n = 1;  // the UTF-8 sequence's length, from its lead byte
      const auto lead = static_cast<unsigned char>(c);
      if (lead >= 0xf0) n = 4;
      else if (lead >= 0xe0) n = 3;
      else if (lead >= 0xc0) n = 2;
      const std::string seq = s.substr(i, n);
      const char* as = "?";
      for (const auto& [from, to] : kKnown)
        if (seq == from) as = to;
      out += as;
      i += n;
      continue;
    }
    switch (c) {
      case '&': case '%': case '$': case '#': case '_': case '{': case '}': out += std::string("\\") + c; break;
      case '~': out += "\\textasciitilde{}"; break;
      case '^': out += "\\textasciicircum{}"; break;
      case '\\': out += "\\textbackslash{}"; break;
      case '<': out += "\\textless{}"; break;
      case '>': out += "\\textgreater{}"; break;
      case '|': out += "\\textbar{}"; break;
      default: out += c;
    }
    ++i;
  }
  return out;
}

std::string intervalCell(const Json& j, int decimals) {
  if (j["estimate"].is_null()) return "--";
  std::string s = formatted("%.*f", decimals, j["estimate"].get<double>());
  if (!j["lo"].is_null()) s += formatted(" [%.*f, %.*f]", decimals, j["lo"].get<double>(), decimals, j["hi"].get<double>());
  return s;
}

}  // namespace glossy::study
