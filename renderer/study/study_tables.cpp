#include "renderer/study/study_tables.h"

#include "materials/core/text.h"

#include <optional>
#include <vector>

namespace glossy::study {

namespace {

using Json = nlohmann::ordered_json;
using Opt = std::optional<double>;

Json num(const Opt& v) { return v ? Json(*v) : Json(nullptr); }

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
    {"flip", "flip", [](const StudyRow& r) { return num(r.flip); }},
    {"flip_lo", "flipLo", [](const StudyRow& r) { return num(r.flipLo); }},
    {"flip_hi", "flipHi", [](const StudyRow& r) { return num(r.flipHi); }},
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

// A value as its CSV field: a figure in full (%.17g), absent as an empty field, a flag as 1 or 0.
std::string csvCell(const Json& v) {
  if (v.is_null()) return "";
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  if (v.is_number_float()) return formatted("%.17g", v.get<double>());
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
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': case '%': case '$': case '#': case '_': case '{': case '}': out += std::string("\\") + c; break;
      case '~': out += "\\textasciitilde{}"; break;
      case '^': out += "\\textasciicircum{}"; break;
      case '\\': out += "\\textbackslash{}"; break;
      default: out += c;
    }
  }
  return out;
}

std::string intervalCell(const Json& j) {
  if (j["estimate"].is_null()) return "--";
  std::string s = formatted("%.4f", j["estimate"].get<double>());
  if (!j["lo"].is_null()) s += formatted(" [%.4f, %.4f]", j["lo"].get<double>(), j["hi"].get<double>());
  return s;
}

std::string modelsTex(const nlohmann::ordered_json& models, int materials) {
  std::string out =
      "% glossy study: per-model results (needs \\usepackage{booktabs}). Intervals: 95 % percentile bootstrap over materials.\n"
      "\\begin{tabular}{lrrrll}\n\\toprule\n"
      "Model & Closest & Tied & Mean rank & Mean $r^*$ [95\\,\\% CI] & Median $r^*$ [95\\,\\% CI] \\\\\n\\midrule\n";
  for (const Json& m : models) {
    out += latexEscape(m["label"].get<std::string>()) + " & " + std::to_string(m["closest"].get<int>()) + " & " +
           std::to_string(m["tied"].get<int>()) + " & " +
           (m["meanRank"].is_null() ? std::string("--") : formatted("%.2f", m["meanRank"].get<double>())) + " & " +
           intervalCell(m["meanRrmse"]) + " & " + intervalCell(m["medianRrmse"]) + " \\\\\n";
  }
  out += "\\bottomrule\n\\end{tabular}\n% " + std::to_string(materials) + " materials.\n";
  return out;
}

}  // namespace glossy::study
