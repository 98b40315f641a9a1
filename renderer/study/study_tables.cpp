#include "renderer/study/study_tables.h"

#include "materials/core/text.h"

#include <optional>
#include <vector>

namespace glossy::study {

namespace {

using Json = nlohmann::ordered_json;
using Opt = std::optional<double>;

Json num(const Opt& v) { return v ? Json(*v) : Json(nullptr); }

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string csvNum(const Opt& v) { return v ? formatted("%.17g", *v) : ""; }

}  // namespace

std::string rowsCsv(std::span<const StudyRow> rows) {
  std::string out =
      "material,database,material_class,lighting,scene,layer,label,fit,fit_metric,fit_source,e1,e2,rrmse,rrmse_lo,rrmse_hi,"
      "flip,flip_lo,flip_hi,luminance_ratio,closest,tied,warning,sheet,width,height,spp,seed\n";
  for (const StudyRow& r : rows) {
    const std::vector<std::string> f = {r.material, r.database, r.materialClass, r.lighting, r.scene, r.layer, r.label,
                                        r.fit, r.fitMetric, r.fitSource, csvNum(r.e1), csvNum(r.e2), csvNum(r.rrmse),
                                        csvNum(r.rrmseLo), csvNum(r.rrmseHi), csvNum(r.flip), csvNum(r.flipLo),
                                        csvNum(r.flipHi), csvNum(r.luminanceRatio), r.closest ? "1" : "0",
                                        r.tied ? "1" : "0", r.warning, r.sheet, std::to_string(r.width),
                                        std::to_string(r.height), std::to_string(r.spp), std::to_string(r.seed)};
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (i) out += ',';
      out += csvField(f[i]);
    }
    out += '\n';
  }
  return out;
}

nlohmann::ordered_json rowsJson(std::span<const StudyRow> rows) {
  Json out = Json::array();
  for (const StudyRow& r : rows) {
    Json j;
    j["material"] = r.material;
    j["database"] = r.database;
    j["materialClass"] = r.materialClass;
    j["lighting"] = r.lighting;
    j["scene"] = r.scene;
    j["layer"] = r.layer;
    j["label"] = r.label;
    j["fit"] = r.fit;
    j["fitMetric"] = r.fitMetric;
    j["fitSource"] = r.fitSource;
    j["e1"] = num(r.e1);
    j["e2"] = num(r.e2);
    j["rrmse"] = num(r.rrmse);
    j["rrmseLo"] = num(r.rrmseLo);
    j["rrmseHi"] = num(r.rrmseHi);
    j["flip"] = num(r.flip);
    j["flipLo"] = num(r.flipLo);
    j["flipHi"] = num(r.flipHi);
    j["luminanceRatio"] = num(r.luminanceRatio);
    j["closest"] = r.closest;
    j["tied"] = r.tied;
    j["warning"] = r.warning;
    j["sheet"] = r.sheet;
    j["width"] = r.width;
    j["height"] = r.height;
    j["spp"] = r.spp;
    j["seed"] = r.seed;
    out.push_back(j);
  }
  return out;
}

namespace {

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

}  // namespace

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
