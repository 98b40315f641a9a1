#include "renderer/study/study_verdicts.h"

#include <algorithm>

namespace glossy::study {

namespace {

// A sheet's verdict (the closest model, a tie or none) and its models in order of rRMSE.
Json sheetVerdict(const SheetKey& key, const std::map<std::string, const StudyRow*>& sheet) {
  Json j;
  j["lighting"] = key.lighting;
  j["scene"] = key.scene;
  std::vector<std::string> tied;
  std::string closest, warning;
  std::vector<std::pair<double, std::string>> byError;
  for (const auto& [label, row] : sheet) {
    if (row->closest) closest = label;
    if (row->tied) tied.push_back(label);
    if (!row->warning.empty()) warning = row->warning;
    byError.emplace_back(*row->rrmse, label);
  }
  std::sort(byError.begin(), byError.end());
  j["verdict"] = !closest.empty() ? "closest" : (!tied.empty() ? "tie" : "none");
  j["models"] = !closest.empty() ? Json::array({closest}) : Json(tied);
  Json ranking = Json::array();
  for (const auto& [e, label] : byError) ranking.push_back(label);
  j["ranking"] = ranking;
  j["warning"] = warning;
  return j;
}

// The model of the best mean rank over the material's sheets (`scores`: each sheet's rRMSE of the `common`
// models), and how many of the sheets' verdicts (`sheets`, as sheetVerdict writes them) name another.
Json acrossLightings(const std::vector<std::string>& common, const std::vector<std::vector<double>>& scores, const Json& sheets) {
  Json across;
  if (common.empty()) {
    across["model"] = nullptr;
    across["reason"] = "no model on every sheet of the material";
    return across;
  }
  std::vector<double> meanRank(common.size(), 0.0);
  for (const auto& row : scores) {
    const auto r = averageRanks(row);
    for (std::size_t k = 0; k < r.size(); ++k) meanRank[k] += r[k] / double(scores.size());
  }
  const std::size_t best = std::size_t(std::min_element(meanRank.begin(), meanRank.end()) - meanRank.begin());
  across["model"] = common[best];
  across["meanRank"] = meanRank[best];
  // A flip: a sheet whose verdict names a model and not the one across lightings.
  int flips = 0, withVerdict = 0;
  std::set<std::string> verdicts;
  for (const Json& j : sheets) {
    if (j["verdict"] == "none") continue;
    ++withVerdict;
    verdicts.insert(j["models"].dump());
    const auto& named = j["models"];
    if (std::find(named.begin(), named.end(), Json(common[best])) == named.end()) ++flips;
  }
  across["sheetsWithVerdict"] = withVerdict;
  across["flips"] = flips;
  across["distinctVerdicts"] = int(verdicts.size());
  return across;
}

// Kendall's W: how far the material's sheets agree on the ranks of the models on every sheet.
Json rankAgreement(const std::vector<std::vector<double>>& scores, std::size_t models) {
  Json w;
  const auto kw = kendallW(scores);
  w["value"] = num(kw);
  w["lightings"] = int(scores.size());
  w["models"] = int(models);
  if (!kw)
    w["reason"] = scores.size() < 2 ? "fewer than 2 sheets" : (models < 2 ? "fewer than 2 models on every sheet" : "every sheet ties every model");
  return w;
}

}  // namespace

Json perMaterial(const Study& s) {
  Json out = Json::array();
  for (const std::string& m : s.materials) {
    Json jm;
    jm["material"] = m;
    jm["database"] = s.database.at(m);
    jm["class"] = s.materialClass.at(m);
    std::vector<const std::map<std::string, const StudyRow*>*> sheets;
    Json js = Json::array();
    for (const auto& [key, sheet] : s.sheets) {
      if (key.material != m) continue;
      sheets.push_back(&sheet);
      js.push_back(sheetVerdict(key, sheet));
    }
    // The models on every sheet of this material: rankings across lightings compare like with like.
    std::vector<std::string> common;
    for (const std::string& label : s.models)
      if (std::all_of(sheets.begin(), sheets.end(), [&](auto* sh) { return sh->count(label) > 0; })) common.push_back(label);
    std::vector<std::vector<double>> scores;
    for (auto* sh : sheets) {
      std::vector<double> row;
      for (const std::string& label : common) row.push_back(*sh->at(label)->rrmse);
      scores.push_back(row);
    }
    jm["sheets"] = js;
    jm["acrossLightings"] = acrossLightings(common, scores, js);
    jm["kendallW"] = rankAgreement(scores, common.size());
    out.push_back(jm);
  }
  return out;
}

VerdictCounts verdictCounts(const Study& s) {
  VerdictCounts v;
  for (const auto& [key, sheet] : s.sheets) {
    bool one = false, tie = false;
    for (const auto& [model, row] : sheet) {
      one = one || row->closest;
      tie = tie || row->tied;
      v.clamped += row->rrmseClamped ? 1 : 0;
    }
    v.decided += one ? 1 : 0;
    v.tied += !one && tie ? 1 : 0;
  }
  v.none = int(s.sheets.size()) - v.decided - v.tied;
  return v;
}

Json countsJson(const Study& s, const VerdictCounts& v) {
  Json counts;
  counts["rows"] = int(s.all.size());
  counts["rowsUsed"] = int(s.used.size());
  counts["rowsSkippedWithoutRrmse"] = s.skipped;
  counts["materials"] = int(s.materials.size());
  counts["sheets"] = int(s.sheets.size());
  counts["models"] = int(s.models.size());
  counts["sheetsDecided"] = v.decided;
  counts["sheetsTied"] = v.tied;
  counts["sheetsWithoutVerdict"] = v.none;
  counts["rowsRrmseClamped"] = v.clamped;
  return counts;
}

// How noisy the sheets' r* are: their 95 % intervals' half-widths over the rows that have one, and the rows
// whose noise is as large as r* itself. Resampling materials carries this noise into every interval's
// spread; where it is large it also biases r* low and weakens the correlations built on it, which no
// interval includes (docs/study.md, "Render noise"), so a reader of the figures needs its size.
Json renderNoiseJson(const Study& s) {
  std::vector<double> half;
  int asLarge = 0;
  for (const StudyRow* r : s.used)
    if (r->rrmse && r->rrmseLo && r->rrmseHi) {
      half.push_back(0.5 * (*r->rrmseHi - *r->rrmseLo));
      asLarge += half.back() >= *r->rrmse ? 1 : 0;
    }
  std::sort(half.begin(), half.end());
  Json j;
  j["what"] = "the half-widths of the sheets' 95 % r* intervals (render noise) over the rows that have one";
  j["rows"] = int(half.size());
  j["medianHalfWidth"] = half.empty() ? Json(nullptr) : Json(quantileSorted(half, 0.5));
  j["p90HalfWidth"] = half.empty() ? Json(nullptr) : Json(quantileSorted(half, 0.9));
  j["rowsHalfWidthAtLeastRrmse"] = asLarge;
  if (half.empty()) j["reason"] = "no row has an r* interval";
  return j;
}

}  // namespace glossy::study
