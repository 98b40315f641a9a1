#include "renderer/study/study_ranks.h"

#include "renderer/study/study_intervals.h"

#include <algorithm>
#include <map>
#include <numeric>

namespace glossy::study {

namespace {

constexpr double kAlpha = 0.05;

// The materials with every model (`complete`) and, a block per material, their rRMSE of each model.
std::vector<std::vector<double>> completeBlocks(const Study& s, std::vector<std::size_t>& complete) {
  std::vector<std::vector<double>> blocks;
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    if (std::any_of(s.rrmse[i].begin(), s.rrmse[i].end(), [](const Opt& v) { return !v; })) continue;
    complete.push_back(i);
    std::vector<double> b;
    for (const Opt& v : s.rrmse[i]) b.push_back(*v);
    blocks.push_back(b);
  }
  return blocks;
}

// Every pair of models by the Wilcoxon signed-rank test on the blocks, Holm-corrected: which pairs differ,
// and each pair's entry of results.json.
void wilcoxonPairs(const Study& s, const std::vector<std::vector<double>>& blocks, RankTests& t) {
  const std::size_t nk = s.models.size();
  t.pHolm.assign(nk, std::vector<Opt>(nk));
  t.different.assign(nk, std::vector<bool>(nk, false));
  std::vector<std::pair<std::size_t, std::size_t>> tested;
  std::vector<double> raw;
  std::vector<Json> entries;
  for (std::size_t a = 0; a < nk; ++a)
    for (std::size_t b = a + 1; b < nk; ++b) {
      std::vector<double> x, y;
      for (const auto& blk : blocks) {
        x.push_back(blk[a]);
        y.push_back(blk[b]);
      }
      std::string reason;
      const auto w = wilcoxonSignedRank(x, y, &reason);
      Json j;
      j["a"] = s.models[a];
      j["b"] = s.models[b];
      if (w) {
        j["n"] = w->n;
        j["zeros"] = w->zeros;
        j["statistic"] = w->statistic;
        j["p"] = w->p;
        j["method"] = w->method;
        t.methods.insert(w->method);
        tested.emplace_back(a, b);
        raw.push_back(w->p);
      } else {
        j["p"] = nullptr;
        j["reason"] = reason;
      }
      entries.push_back(j);
    }
  const auto adjusted = holm(raw);
  for (std::size_t i = 0; i < tested.size(); ++i) {
    const auto [a, b] = tested[i];
    t.pHolm[a][b] = t.pHolm[b][a] = adjusted[i];
    t.different[a][b] = t.different[b][a] = adjusted[i] < kAlpha;
  }
  for (Json& j : entries) {
    const std::size_t a = std::size_t(std::find(s.models.begin(), s.models.end(), j["a"].get<std::string>()) - s.models.begin());
    const std::size_t b = std::size_t(std::find(s.models.begin(), s.models.end(), j["b"].get<std::string>()) - s.models.begin());
    j["pHolm"] = num(t.pHolm[a][b]);
    j["significant"] = bool(t.different[a][b]);
    t.wilcoxon.push_back(j);
  }
}

// Rank order (mean rank, then label) and the cliques: maximal runs of models no pair of which differs.
void rankOrderAndCliques(RankTests& t, std::size_t nk) {
  t.rankOrder.resize(nk);
  std::iota(t.rankOrder.begin(), t.rankOrder.end(), 0);
  if (!t.friedman) return;
  const auto& mr = t.friedman->meanRanks;
  std::stable_sort(t.rankOrder.begin(), t.rankOrder.end(), [&](std::size_t a, std::size_t b) { return mr[a] < mr[b]; });
  int lastEnd = -1;
  for (int i = 0; i < int(nk); ++i) {
    int j = i;
    while (j + 1 < int(nk)) {
      bool ok = true;
      for (int k = i; k <= j && ok; ++k) ok = !t.different[t.rankOrder[std::size_t(k)]][t.rankOrder[std::size_t(j + 1)]];
      if (!ok) break;
      ++j;
    }
    if (j > i && j > lastEnd) {
      t.cliques.emplace_back(i, j);
      lastEnd = j;
    }
  }
}

// The share of materials (among `units`) on which model a is closer than model b (ties count one half).
Opt closerShare(const Study& s, std::size_t a, std::size_t b, const std::vector<std::size_t>& materials) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t i : materials) {
    const Opt x = s.rrmse[i][a], y = s.rrmse[i][b];
    if (!x || !y) continue;
    sum += *x < *y ? 1.0 : (*x == *y ? 0.5 : 0.0);
    ++n;
  }
  if (n == 0) return std::nullopt;
  return sum / n;
}

Json pairwiseTable(const Study& s, const std::vector<std::size_t>& materials, const AnalysisOptions& o, const std::string& key) {
  Json out = Json::array();
  for (std::size_t a = 0; a < s.models.size(); ++a)
    for (std::size_t b = 0; b < s.models.size(); ++b) {
      if (a == b) continue;
      int n = 0;
      for (std::size_t i : materials) n += s.rrmse[i][a] && s.rrmse[i][b] ? 1 : 0;
      const auto iv = materialInterval(
          materials.size(),
          [&](const std::vector<std::size_t>& idx) {
            std::vector<std::size_t> drawn;
            for (std::size_t i : idx) drawn.push_back(materials[i]);
            return closerShare(s, a, b, drawn);
          },
          o.resamples, seedFor(o.seed, "closer/" + key + "/" + s.models[a] + "/" + s.models[b]), std::size_t(n));
      Json j;
      j["x"] = s.models[a];
      j["y"] = s.models[b];
      j["materials"] = n;
      j["share"] = intervalJson(iv);
      out.push_back(j);
    }
  return out;
}

}  // namespace

RankTests rankTests(const Study& s) {
  RankTests t;
  const std::size_t nk = s.models.size();
  const std::vector<std::vector<double>> blocks = completeBlocks(s, t.complete);
  t.friedman = friedman(blocks);
  if (nk < 2)
    t.friedmanReason = "fewer than 2 models";
  else if (blocks.size() < kTestMinMaterials)
    t.friedmanReason = tooFewForTest(blocks.size());
  else if (!t.friedman)
    t.friedmanReason = "every material ties every model";
  t.friedmanTested = t.friedman && blocks.size() >= kTestMinMaterials;
  wilcoxonPairs(s, blocks, t);
  rankOrderAndCliques(t, nk);
  return t;
}

Json perModel(const Study& s, const RankTests& t, const AnalysisOptions& o) {
  Json out = Json::array();
  for (std::size_t k = 0; k < s.models.size(); ++k) {
    int sheets = 0, closest = 0, tied = 0, warned = 0, clamped = 0;
    for (const auto& [key, sheet] : s.sheets)
      if (const auto it = sheet.find(s.models[k]); it != sheet.end()) {
        ++sheets;
        closest += it->second->closest ? 1 : 0;
        tied += it->second->tied ? 1 : 0;
        warned += it->second->warning.empty() ? 0 : 1;
        clamped += it->second->rrmseClamped ? 1 : 0;
      }
    std::vector<std::size_t> have;
    for (std::size_t i = 0; i < s.materials.size(); ++i)
      if (s.rrmse[i][k]) have.push_back(i);
    auto values = [&](const std::vector<std::size_t>& idx) {
      std::vector<double> v;
      for (std::size_t i : idx) v.push_back(*s.rrmse[have[i]][k]);
      return v;
    };
    const auto mean = materialInterval(have.size(), [&](const auto& idx) { return meanOf(values(idx)); }, o.resamples,
                                seedFor(o.seed, "mean/" + s.models[k]));
    const auto median = materialInterval(have.size(), [&](const auto& idx) { return medianOf(values(idx)); }, o.resamples,
                                  seedFor(o.seed, "median/" + s.models[k]));
    Json j;
    j["label"] = s.models[k];
    j["fits"] = Json(std::vector<std::string>(s.fitsOf[k].begin(), s.fitsOf[k].end()));
    j["fitSources"] = Json(std::vector<std::string>(s.sourcesOf[k].begin(), s.sourcesOf[k].end()));
    j["sheets"] = sheets;
    j["closest"] = closest;
    j["tied"] = tied;
    j["sheetsWithWarning"] = warned;
    j["rrmseClamped"] = clamped;
    j["materials"] = int(have.size());
    j["meanRank"] = t.friedman ? Json(t.friedman->meanRanks[k]) : Json(nullptr);
    j["meanRrmse"] = intervalJson(mean);
    j["medianRrmse"] = intervalJson(median);
    out.push_back(j);
  }
  return out;
}

// The Friedman test and the Holm–Wilcoxon pairs with the cliques they leave, as results.json has them.
void addRankTests(const Study& s, const RankTests& t, Json& results) {
  Json jf;
  jf["materials"] = int(t.complete.size());
  jf["materialsLeftOut"] = int(s.materials.size() - t.complete.size());
  jf.update(friedmanJson(t.friedmanTested ? t.friedman : std::nullopt, t.friedmanReason));
  results["friedman"] = jf;
  Json jw;
  jw["alpha"] = kAlpha;
  jw["correction"] = "Holm";
  jw["zeroMethod"] = "Wilcoxon (zero differences dropped)";
  jw["methods"] = Json(std::vector<std::string>(t.methods.begin(), t.methods.end()));
  jw["pairs"] = t.wilcoxon;
  Json cliques = Json::array();
  for (const auto& [a, b] : t.cliques) {
    Json c = Json::array();
    for (int i = a; i <= b; ++i) c.push_back(s.models[t.rankOrder[std::size_t(i)]]);
    cliques.push_back(c);
  }
  jw["cliques"] = cliques;
  results["wilcoxon"] = jw;
}

// Which model is closer than which, on what share of materials: over all, per database, per material class.
Json closerThan(const Study& s, const AnalysisOptions& options) {
  std::vector<std::size_t> all(s.materials.size());
  std::iota(all.begin(), all.end(), 0);
  Json pairwise;
  pairwise["overall"] = pairwiseTable(s, all, options, "all");
  Json byDb, byClass;
  std::map<std::string, std::vector<std::size_t>> dbs, classes;
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    dbs[s.database.at(s.materials[i])].push_back(i);
    if (!s.materialClass.at(s.materials[i]).empty()) classes[s.materialClass.at(s.materials[i])].push_back(i);
  }
  for (const auto& [db, mats] : dbs) byDb[db.empty() ? "(none)" : db] = pairwiseTable(s, mats, options, "db/" + db);
  for (const auto& [c, mats] : classes) byClass[c] = pairwiseTable(s, mats, options, "class/" + c);
  pairwise["byDatabase"] = byDb.is_null() ? Json::object() : byDb;
  pairwise["byClass"] = byClass.is_null() ? Json::object() : byClass;
  return pairwise;
}

}  // namespace glossy::study
