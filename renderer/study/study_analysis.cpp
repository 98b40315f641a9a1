// The study's statistics (docs/study.md, "The statistics"). The unit of the study is the material: every
// figure of a model on a material is first averaged over the material's sheets (its lightings and scenes),
// and tests, intervals and correlations treat materials as the independent draws — a material's
// lightings are not independent evidence about the models, so bootstraps resample materials and keep
// their sheets together.
#include "renderer/study/study_analysis.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/plot/svg_to_png.h"
#include "renderer/sheet/comparison_grid.h"
#include "renderer/study/perceptual.h"
#include "renderer/study/study_figures.h"
#include "renderer/study/study_intervals.h"
#include "renderer/study/study_latex.h"
#include "renderer/study/study_lighting.h"
#include "renderer/study/study_methods.h"
#include "renderer/study/study_people.h"
#include "renderer/study/study_provenance.h"
#include "renderer/study/study_tables.h"
#include "renderer/study/study_statistics.h"
#include "renderer/util/atomic_file.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

namespace glossy::study {

namespace {

using Json = nlohmann::ordered_json;
using Opt = std::optional<double>;

constexpr double kAlpha = 0.05;

Json num(const Opt& v) { return v ? Json(*v) : Json(nullptr); }

void checkFinite(const StudyRow& r, const Opt& v, const char* what) {
  if (v && !std::isfinite(*v))
    throw InputError("study row " + printableLine(r.material, 80) + " / " + printableLine(r.lighting, 40) + " / " +
                     printableLine(r.label, 40) + ": " + what + " is not a finite number");
}

struct SheetKey {
  std::string material, lighting, scene;
  auto operator<=>(const SheetKey&) const = default;
};

struct Study {
  std::vector<StudyRow> all;   // every row, canonical order
  std::vector<const StudyRow*> used;
  int skipped = 0;
  std::vector<std::string> models;     // labels, sorted
  std::vector<std::string> materials;  // sorted
  std::map<std::string, std::string> database, materialClass;
  std::map<SheetKey, std::map<std::string, const StudyRow*>> sheets;
  // Per material and model: the figure averaged over the material's sheets.
  std::vector<std::vector<Opt>> rrmse, flip, e1, e2;
  // Per model: its first row's fit and source (for its colour), and every fit and source its rows carry
  // (a model's label covers the published fit on one database and glossy's on another).
  std::vector<std::string> fitOf, sourceOf;
  std::vector<std::set<std::string>> fitsOf, sourcesOf;
};

// A bootstrap's statistic: the mean of the defined values among the materials drawn.
auto meanOfDrawn(const std::vector<Opt>& values) {
  return [&values](const std::vector<std::size_t>& drawn) {
    std::vector<double> v;
    for (std::size_t i : drawn)
      if (values[i]) v.push_back(*values[i]);
    return meanOf(v);
  };
}

Study readRows(std::span<const StudyRow> rows) {
  Study s;
  s.all.assign(rows.begin(), rows.end());
  std::sort(s.all.begin(), s.all.end(), [](const StudyRow& a, const StudyRow& b) {
    return std::tie(a.material, a.lighting, a.scene, a.label, a.fit, a.fitSource) <
           std::tie(b.material, b.lighting, b.scene, b.label, b.fit, b.fitSource);
  });
  std::set<std::string> models, materials;
  std::map<std::tuple<std::string, std::string, std::string, std::string>, const StudyRow*> seen;
  for (const StudyRow& r : s.all) {
    if (r.material.empty() || r.label.empty())
      throw InputError("study row without a material or model label (" + printableLine(r.sheet, 80) + ")");
    checkFinite(r, r.e1, "E1");
    checkFinite(r, r.e2, "E2");
    checkFinite(r, r.rrmse, "rrmse");
    checkFinite(r, r.rrmseLo, "rrmse's lower bound");
    checkFinite(r, r.rrmseHi, "rrmse's upper bound");
    checkFinite(r, r.flip, "FLIP");
    checkFinite(r, r.flipLo, "FLIP's lower bound");
    checkFinite(r, r.flipHi, "FLIP's upper bound");
    checkFinite(r, r.deltaEItp, "ΔE_ITP");
    checkFinite(r, r.ssim, "SSIM");
    checkFinite(r, r.luminanceRatio, "the luminance ratio");
    auto& sheet = s.sheets[{r.material, r.lighting, r.scene}];
    // One row per model and sheet: a sheet showing two fits of one model (the published and glossy's)
    // could not say which of them ranks where.
    const auto [first, fresh] = seen.emplace(std::tuple(r.material, r.lighting, r.scene, r.label), &r);
    if (!fresh)
      throw InputError("study: model " + printableLine(r.label, 40) + " appears twice on the sheet of " +
                       printableLine(r.material, 80) + " / " + printableLine(r.lighting, 40) + " / " + printableLine(r.scene, 40) +
                       " (fits " + printableLine(first->second->fit, 40) + " and " + printableLine(r.fit, 40) + ")");
    if (!r.rrmse) {
      ++s.skipped;
      continue;
    }
    sheet[r.label] = &r;
    s.used.push_back(&r);
    models.insert(r.label);
    materials.insert(r.material);
    if (!s.database.count(r.material)) s.database[r.material] = r.database;
    if (!s.materialClass.count(r.material) || s.materialClass[r.material].empty()) s.materialClass[r.material] = r.materialClass;
  }
  for (auto it = s.sheets.begin(); it != s.sheets.end();) it = it->second.empty() ? s.sheets.erase(it) : std::next(it);
  s.models.assign(models.begin(), models.end());
  s.materials.assign(materials.begin(), materials.end());
  s.fitOf.resize(s.models.size());
  s.sourceOf.resize(s.models.size());
  s.fitsOf.resize(s.models.size());
  s.sourcesOf.resize(s.models.size());
  const auto nm = s.materials.size(), nk = s.models.size();
  for (auto* t : {&s.rrmse, &s.flip, &s.e1, &s.e2}) t->assign(nm, std::vector<Opt>(nk));
  for (std::size_t i = 0; i < nm; ++i)
    for (std::size_t k = 0; k < nk; ++k) {
      std::vector<double> r, f, a, b;
      for (const auto& [key, sheet] : s.sheets) {
        if (key.material != s.materials[i]) continue;
        const auto it = sheet.find(s.models[k]);
        if (it == sheet.end()) continue;
        const StudyRow& row = *it->second;
        if (s.fitOf[k].empty()) {
          s.fitOf[k] = row.fit;
          s.sourceOf[k] = row.fitSource;
        }
        s.fitsOf[k].insert(row.fit);
        s.sourcesOf[k].insert(row.fitSource);
        r.push_back(*row.rrmse);
        if (row.flip) f.push_back(*row.flip);
        if (row.e1) a.push_back(*row.e1);
        if (row.e2) b.push_back(*row.e2);
      }
      s.rrmse[i][k] = meanOf(r);
      s.flip[i][k] = meanOf(f);
      s.e1[i][k] = meanOf(a);
      s.e2[i][k] = meanOf(b);
    }
  return s;
}

// ---- per material: verdicts under each lighting, across lightings, and their agreement -----------------

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

// ---- per model: wins, ranks and their tests, error levels, pairwise shares ---------------------------------

struct RankTests {
  std::optional<FriedmanResult> friedman;
  std::string friedmanReason;
  bool friedmanTested = false;  // the mean ranks stand on any number of materials, the test on kTestMinMaterials
  std::vector<std::size_t> complete;  // materials with every model
  std::vector<std::vector<Opt>> pHolm;  // [a][b]
  std::vector<std::vector<bool>> different;
  std::vector<std::pair<int, int>> cliques;  // in rank order
  std::vector<std::size_t> rankOrder;
  Json wilcoxon = Json::array();
  std::set<std::string> methods;
};

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

Json perModel(const Study& s, const RankTests& t, const AnalysisOptions& o, std::vector<Interval>& meanIv) {
  Json out = Json::array();
  meanIv.clear();
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
    meanIv.push_back(mean);
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

// ---- the paper's claim: does BRDF-space error predict image-space error? ----------------------------------

using Column = std::vector<std::vector<Opt>> Study::*;

struct Pair {
  std::vector<double> x, y;
};

// (BRDF error, image error) of every model on the drawn materials.
Pair pooled(const Study& s, Column brdf, Column image, const std::vector<std::size_t>& materials) {
  Pair p;
  for (std::size_t i : materials)
    for (std::size_t k = 0; k < s.models.size(); ++k) {
      const Opt x = (s.*brdf)[i][k], y = (s.*image)[i][k];
      if (x && y) {
        p.x.push_back(*x);
        p.y.push_back(*y);
      }
    }
  return p;
}

// Whether the model best under `brdf` is best under `image` on material i (ties: any shared best model).
Opt bestAgrees(const Study& s, Column brdf, Column image, std::size_t i) {
  std::vector<std::size_t> ks;
  for (std::size_t k = 0; k < s.models.size(); ++k)
    if ((s.*brdf)[i][k] && (s.*image)[i][k]) ks.push_back(k);
  if (ks.size() < 2) return std::nullopt;
  double bx = INFINITY, by = INFINITY;
  for (std::size_t k : ks) {
    bx = std::min(bx, *(s.*brdf)[i][k]);
    by = std::min(by, *(s.*image)[i][k]);
  }
  for (std::size_t k : ks)
    if (*(s.*brdf)[i][k] == bx && *(s.*image)[i][k] == by) return 1.0;
  return 0.0;
}

// The rank correlations the study reports, by their name in results.json.
using Corr = std::optional<double> (*)(const std::vector<double>&, const std::vector<double>&);
const std::pair<const char*, Corr> kCorrelations[] = {{"spearman", spearman}, {"kendallTauB", kendallTauB}};

// A BRDF-space error's correlations with an image error pooled over every (material, model) pair; `key`
// names the two ("E1/rrmse"), `rho` is set to the Spearman ρ.
Json pooledCorrelations(const Study& s, const AnalysisOptions& o, Column brdf, Column image, const std::string& key, Interval& rho) {
  std::vector<std::size_t> all(s.materials.size());
  std::iota(all.begin(), all.end(), 0);
  Json jp;
  jp["pairs"] = int(pooled(s, brdf, image, all).x.size());
  // Not a structured binding: clang before 16 cannot capture one in the lambda (the fuzzers' build is clang).
  for (const auto& named : kCorrelations) {
    const char* const cname = named.first;
    const Corr corr = named.second;
    const auto iv = materialInterval(
        all.size(),
        [&](const std::vector<std::size_t>& idx) {
          const Pair p = pooled(s, brdf, image, idx);
          return corr(p.x, p.y);
        },
        o.resamples, seedFor(o.seed, "pooled/" + key + "/" + cname));
    jp[cname] = intervalJson(iv);
    if (std::string(cname) == "spearman") rho = iv;
  }
  return jp;
}

// The same within each material, across its models; then the mean over materials, resampling materials.
Json withinMaterialCorrelations(const Study& s, const AnalysisOptions& o, Column brdf, Column image, const std::string& key, Interval& rho) {
  Json jw;
  for (const auto& [cname, corr] : kCorrelations) {
    std::vector<Opt> within(s.materials.size());
    int defined = 0;
    for (std::size_t i = 0; i < s.materials.size(); ++i) {
      const Pair p = pooled(s, brdf, image, {i});
      within[i] = corr(p.x, p.y);
      defined += within[i] ? 1 : 0;
    }
    const auto wiv = materialInterval(s.materials.size(), meanOfDrawn(within), o.resamples, seedFor(o.seed, "within/" + key + "/" + cname),
                                      std::size_t(defined));
    jw[cname] = intervalJson(wiv);
    if (std::string(cname) == "spearman") rho = wiv;
    jw["materials"] = defined;
    jw["materialsUndefined"] = int(s.materials.size()) - defined;
  }
  return jw;
}

// The share of materials on which the model best under the BRDF-space error is best in the image too.
Json bestIsImageBest(const Study& s, const AnalysisOptions& o, Column brdf, Column image, const std::string& key) {
  std::vector<Opt> agrees(s.materials.size());
  int n = 0;
  for (std::size_t i = 0; i < s.materials.size(); ++i) n += (agrees[i] = bestAgrees(s, brdf, image, i)) ? 1 : 0;
  const auto share = materialInterval(s.materials.size(), meanOfDrawn(agrees), o.resamples, seedFor(o.seed, "best/" + key), std::size_t(n));
  Json jb;
  jb["materials"] = n;
  jb["share"] = intervalJson(share);
  return jb;
}

// Whether E2 ranks the fits more like the image than E1 does, asked two ways, each a paired interval
// (both ρ on the same resampled materials, not two intervals compared by eye). Pooled: the difference
// of the ρ over every (material, model) pair — across materials, where a material's overall level
// dominates. Within: each material's ρ across its fits, E2's minus E1's, then the mean over materials —
// Löw et al.'s question, whether the metric ranks one material's fits as the image does.
struct E2MinusE1 {
  Interval pooled, within;
  int materials = 0;  // with both ρ within the material
};

E2MinusE1 e2MinusE1(const Study& s, const AnalysisOptions& o, Column image, const std::string& name) {
  E2MinusE1 d;
  d.pooled = materialInterval(
      s.materials.size(),
      [&](const std::vector<std::size_t>& idx) -> Opt {
        const Pair p1 = pooled(s, &Study::e1, image, idx), p2 = pooled(s, &Study::e2, image, idx);
        const Opt a = spearman(p1.x, p1.y), b = spearman(p2.x, p2.y);
        if (!a || !b) return std::nullopt;
        return *b - *a;
      },
      o.resamples, seedFor(o.seed, "e2-e1/" + name));
  std::vector<Opt> withinDiff(s.materials.size());
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    const Pair p1 = pooled(s, &Study::e1, image, {i}), p2 = pooled(s, &Study::e2, image, {i});
    const Opt a = spearman(p1.x, p1.y), b = spearman(p2.x, p2.y);
    if (a && b) withinDiff[i] = *b - *a;
    d.materials += withinDiff[i] ? 1 : 0;
  }
  d.within = materialInterval(s.materials.size(), meanOfDrawn(withinDiff), o.resamples, seedFor(o.seed, "e2-e1/within/" + name),
                              std::size_t(d.materials));
  return d;
}

// The summary's lines on the claim: E1's and E2's Spearman ρ with rRMSE (`pooledRho`, `withinRho` by
// "E1/rrmse", "E2/rrmse") and their difference, pooled and within materials.
std::string claimHeadline(const std::map<std::string, Interval>& pooledRho, const std::map<std::string, Interval>& withinRho,
                          const E2MinusE1& d) {
  const auto verdict = [](const Interval& iv) -> std::string {
    if (!iv.lo || !iv.hi) return iv.estimate ? " — not decided (no interval)." : " — not decided.";
    if (*iv.lo > 0.0) return " — E2 predicts image error better than E1.";
    if (*iv.hi < 0.0) return " — E1 predicts image error better than E2.";
    return " — no difference between E1 and E2 shown.";
  };
  return "Does E2 predict image error (rRMSE) better than E1? Spearman ρ, two questions:\n"
         "  Across materials (pooled over every material and model): E1 " + intervalText(pooledRho.at("E1/rrmse"), "%.3f") +
         ", E2 " + intervalText(pooledRho.at("E2/rrmse"), "%.3f") + "; E2 − E1 " + intervalText(d.pooled, "%.3f") + verdict(d.pooled) +
         "\n  Across a material's fits (within each material, then the mean; Löw et al.'s question): E1 " +
         intervalText(withinRho.at("E1/rrmse"), "%.3f") + ", E2 " + intervalText(withinRho.at("E2/rrmse"), "%.3f") +
         "; E2 − E1 " + intervalText(d.within, "%.3f") + " over " + std::to_string(d.materials) + " materials" + verdict(d.within);
}

Json brdfVsImage(const Study& s, const AnalysisOptions& o, Json& differences, std::string& headline) {
  Json out = Json::array();
  struct Named {
    const char* name;
    Column column;
  };
  const Named brdfs[] = {{"E1", &Study::e1}, {"E2", &Study::e2}};
  const Named images[] = {{"rrmse", &Study::rrmse}, {"flip", &Study::flip}};
  std::map<std::string, Interval> pooledRho, withinRho;
  for (const auto& img : images)
    for (const auto& br : brdfs) {
      const std::string key = std::string(br.name) + "/" + img.name;
      Json j;
      j["brdf"] = br.name;
      j["image"] = img.name;
      j["pooled"] = pooledCorrelations(s, o, br.column, img.column, key, pooledRho[key]);
      j["withinMaterial"] = withinMaterialCorrelations(s, o, br.column, img.column, key, withinRho[key]);
      j["bestIsImageBest"] = bestIsImageBest(s, o, br.column, img.column, key);
      out.push_back(j);
    }
  for (const auto& img : images) {
    const E2MinusE1 d = e2MinusE1(s, o, img.column, img.name);
    Json j;
    j["image"] = img.name;
    j["pooledSpearman"] = intervalJson(d.pooled);
    Json jw = intervalJson(d.within);
    jw["materials"] = d.materials;
    jw["materialsUndefined"] = int(s.materials.size()) - d.materials;
    j["withinMaterialSpearman"] = jw;
    differences.push_back(j);
    if (std::string(img.name) == "rrmse") headline = claimHeadline(pooledRho, withinRho, d);
  }
  return out;
}

// ---- against people --------------------------------------------------------------------------------------

const char* const kFigureNames[] = {"rrmse", "flip", "E1", "E2"};

// Per material, each figure of exactly this fit's rows (a model's label may cover glossy's fits on other
// materials), averaged over the material's sheets; `label`: the rows' model label (empty: no such rows).
std::vector<std::array<Opt, 4>> figuresOfFit(const Study& s, const PerceptualFit& pf, std::string& label) {
  std::vector<std::array<Opt, 4>> figure(s.materials.size());
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    std::array<std::vector<double>, 4> v;
    for (const StudyRow* r : s.used) {
      if (r->material != s.materials[i] || r->fit != pf.fit || r->fitSource != pf.fitSource) continue;
      if (label.empty()) label = r->label;
      const Opt values[] = {r->rrmse, r->flip, r->e1, r->e2};
      for (std::size_t f = 0; f < 4; ++f)
        if (values[f]) v[f].push_back(*values[f]);
    }
    for (std::size_t f = 0; f < 4; ++f) figure[i][f] = meanOf(v[f]);
  }
  return figure;
}

// The figure whose Spearman ρ with the perceived distance is the highest so far, with its interval.
struct BestFigure {
  std::string name;
  Interval rho;
};

// One figure against the perceived distance over the materials that have both (`points`: (figure,
// distance)): its correlations with their intervals.
Json figureAgainstPeople(const std::vector<plot::Point>& points, const char* figure, const std::string& fit, const AnalysisOptions& o,
                         BestFigure& best) {
  Json jfig;
  jfig["figure"] = figure;
  jfig["materials"] = int(points.size());
  // Not a structured binding: clang before 16 cannot capture one in the lambda (the fuzzers' build is clang).
  for (const auto& named : kCorrelations) {
    const char* const cname = named.first;
    const Corr corr = named.second;
    const auto iv = materialInterval(
        points.size(),
        [&](const std::vector<std::size_t>& idx) {
          std::vector<double> x, y;
          for (std::size_t i : idx) {
            x.push_back(points[i].x);
            y.push_back(points[i].y);
          }
          return corr(x, y);
        },
        o.resamples, seedFor(o.seed, "people/" + fit + "/" + figure + "/" + cname));
    jfig[cname] = intervalJson(iv);
    if (std::string(cname) == "spearman" && iv.estimate && (best.name.empty() || *iv.estimate > *best.rho.estimate)) best = {figure, iv};
  }
  return jfig;
}

// One of the fits the dataset judged, against people: its figures' correlations with the perceived
// distance across materials, its series of the perceptual figure (in `colour`) and its line of the summary.
Json fitAgainstPeople(const Study& s, const AnalysisOptions& o, const PerceptualData& data, const PerceptualFit& pf, const char* colour,
                      std::string& headline, std::vector<PerceptualSeries>& series) {
  std::string label;
  const std::vector<std::array<Opt, 4>> figure = figuresOfFit(s, pf, label);
  Json jf;
  jf["method"] = pf.method;
  jf["fit"] = pf.fit;
  jf["fitSource"] = pf.fitSource;
  if (label.empty()) {
    jf["model"] = nullptr;
    jf["reason"] = "the study has no " + pf.fitSource + " " + pf.fit + " fit";
    return jf;
  }
  jf["model"] = label;
  // The materials with both a glossy figure and a perceived distance.
  std::vector<std::size_t> mats;
  std::vector<double> dist;
  for (std::size_t i = 0; i < s.materials.size(); ++i)
    if (const auto d = data.distance(pf.method, s.materials[i]); d && figure[i][0]) {
      mats.push_back(i);
      dist.push_back(*d);
    }
  jf["materials"] = int(mats.size());
  PerceptualSeries ps;
  ps.name = label;
  ps.note = pf.fitSource + " fit, as " + pf.method;
  const std::string pairName = pf.method + " ↔ " + label + " (" + pf.fitSource + ")";
  ps.style.colour = colour;
  ps.points.resize(std::size(kFigureNames));
  Json figs = Json::array();
  BestFigure best;
  for (std::size_t f = 0; f < std::size(kFigureNames); ++f) {
    for (std::size_t u = 0; u < mats.size(); ++u)
      if (figure[mats[u]][f]) ps.points[f].push_back({*figure[mats[u]][f], dist[u]});
    figs.push_back(figureAgainstPeople(ps.points[f], kFigureNames[f], pf.fit, o, best));
  }
  jf["figures"] = figs;
  jf["agreesBest"] = best.name.empty() ? Json(nullptr) : Json(best.name);
  series.push_back(ps);
  headline += (headline.empty() ? "" : "\n") + std::string("Against people (") + pairName + ", " + std::to_string(mats.size()) +
              " MERL materials): " +
              (best.name.empty() ? std::string("no figure correlates (undefined)")
               : best.rho.lo     ? "the figure that agrees best with the perceived distance is " + best.name + ", Spearman ρ " +
                                   intervalText(best.rho, "%.3f")
                                 // Without an interval the highest ρ is a description of these materials, not a finding.
                                 : "the highest Spearman ρ with the perceived distance is " + best.name + "'s, " + intervalText(best.rho, "%.3f"));
  return jf;
}

Json againstPeople(const Study& s, const AnalysisOptions& o, std::string& headline, std::vector<PerceptualSeries>& series) {
  Json out;
  if (o.perceptualDir.empty()) {
    out["reason"] = "no perceptual data given";
    return out;
  }
  const PerceptualData data = PerceptualData::read(o.perceptualDir);
  out["source"] =
      "Lavoué, Bonneel, Farrugia, Soler, \"Perceptual quality of BRDF approximations: dataset and metrics\", "
      "Computer Graphics Forum 40(2), 2021";
  out["note"] =
      "The dataset's ABC rows are Löw et al. 2012's model with the fit published in their supplement (fitted under E2). "
      "Which ABC variant (Smooth Surface or Microfacet) the study used is not stated in the released data and could not "
      "be checked, so both published ABC fits are compared.";
  Json fits = Json::array();
  headline.clear();
  for (const PerceptualFit& pf : perceptualFits()) {
    const char* const colour = fits.empty() ? "#e69f00" : "#56b4e9";
    fits.push_back(fitAgainstPeople(s, o, data, pf, colour, headline, series));
  }
  out["fits"] = fits;
  return out;
}

std::vector<ModelStyle> modelStyles(const Study& s) {
  static const char* const kPalette[] = {"#e69f00", "#56b4e9", "#009e73", "#cc79a7", "#0072b2",
                                         "#d55e00", "#f0e442", "#999999", "#882255", "#000000"};
  std::vector<ModelStyle> out;
  std::set<std::string> used;
  for (std::size_t k = 0; k < s.models.size(); ++k) {
    ModelStyle m{s.models[k], {}, ""};
    // The sheet's colour for the fit (renderer/sheet/comparison_grid.h), so figures match the sheets.
    const std::string fit = s.fitOf[k].substr(0, s.fitOf[k].find(':', s.fitOf[k].find(':') + 1));
    for (const GridFit& g : gridFits())
      if (g.fit == fit) m.style.colour = std::string(g.colour);
    // Solid lines throughout (a dashed curve of many materials reads as gaps); whose fit it is, the legend says.
    if (s.sourcesOf[k].size() > 1) m.note = "published and glossy's fits";
    else if (s.sourcesOf[k].count("glossy")) m.note = "glossy's fit";
    if (m.style.colour == "#000000" || used.count(m.style.colour)) m.style.colour = kPalette[k % std::size(kPalette)];
    used.insert(m.style.colour);
    out.push_back(m);
  }
  return out;
}

// The sheets' verdicts: how many name one model, a tie, or none (the intervals do not part the models, or
// the sheet warns that they may be too narrow); and the r* that are 0 by clamping.
struct VerdictCounts {
  int decided = 0, tied = 0, none = 0, clamped = 0;
};

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

// The summary's text: counts, verdicts, each model's line, the rank tests, lighting, the claims about
// BRDF-space and image error, a small sample's caveat, and the comparison with people.
std::string summaryText(const Study& s, const RankTests& t, const VerdictCounts& v, const Json& results,
                        const std::string& lightingHeadline, const std::string& claimHeadline, const std::string& peopleHeadline) {
  std::string summary = "Study: " + std::to_string(s.materials.size()) + " materials, " + std::to_string(s.sheets.size()) +
                        " sheets, " + std::to_string(s.models.size()) + " models; " + std::to_string(s.used.size()) + " rows used";
  if (s.skipped) summary += ", " + std::to_string(s.skipped) + " without rRMSE skipped";
  summary += ".\n";
  summary += "Verdicts: " + std::to_string(v.decided) + " of " + std::to_string(s.sheets.size()) + " sheets name one closest model, " +
             std::to_string(v.tied) + " a tie, " + std::to_string(v.none) +
             " none (intervals that do not part the models, or a warning that they may be too narrow)";
  if (v.clamped > 0) summary += "; " + std::to_string(v.clamped) + " r* clamped to 0 (the model within the render noise), ranked as 0";
  summary += ".\n";
  const Json& noise = results["renderNoise"];
  if (!noise["medianHalfWidth"].is_null())
    summary += formatted("Render noise: the sheets' r* intervals have a median half-width of %.2g (90 %% at most %.2g); on %d of %d rows "
                         "it is as large as r* itself. Where it is large, r* reads low and its correlations weaker (docs/study.md, "
                         "\"Render noise\").\n",
                         noise["medianHalfWidth"].get<double>(), noise["p90HalfWidth"].get<double>(),
                         noise["rowsHalfWidthAtLeastRrmse"].get<int>(), noise["rows"].get<int>());
  for (const Json& m : results["models"])
    summary += "  " + m["label"].get<std::string>() + ": closest on " + std::to_string(m["closest"].get<int>()) + " of " +
               std::to_string(m["sheets"].get<int>()) + " sheets, tied on " + std::to_string(m["tied"].get<int>()) +
               "; mean rank " + (m["meanRank"].is_null() ? std::string("—") : formatted("%.2f", m["meanRank"].get<double>())) +
               "; mean rRMSE " + intervalCell(m["meanRrmse"]) +
               (m["rrmseClamped"].get<int>() > 0 ? "; r* clamped to 0 on " + std::to_string(m["rrmseClamped"].get<int>()) : "") + "\n";
  if (t.friedmanTested) {
    summary += formatted("Friedman χ² = %.3f (df %d), p = %.3g", t.friedman->chiSquare, t.friedman->treatments - 1, t.friedman->pChiSquare);
    if (t.friedman->pF) summary += formatted("; Iman–Davenport F p = %.3g", *t.friedman->pF);
    summary += " over " + std::to_string(t.complete.size()) + " materials.\n";
    const std::string groups = joined(results["wilcoxon"]["cliques"], "; ", [](const Json& c) { return c.dump(); });
    summary += "Not significantly different (Holm–Wilcoxon, α = 0.05): " + (groups.empty() ? std::string("none") : groups) + ".\n";
  } else {
    summary += "Friedman test: none (" + t.friedmanReason + ").\n";
  }
  summary += lightingHeadline;
  summary += claimHeadline + "\n";
  if (s.materials.size() < kIntervalMinMaterials)
    summary += "A small sample: no interval (" + tooFewForInterval(s.materials.size()) + ")" +
               (s.materials.size() < kTestMinMaterials ? "; no test (" + tooFewForTest(s.materials.size()) + ")" : std::string()) +
               " — docs/study.md, \"Small samples\", says why.\n";
  if (!peopleHeadline.empty()) summary += peopleHeadline + "\n";
  return summary;
}

// A figure of the analysis: its name, SVG and caption (for results.json, summary.md and the report page).
struct StudyFigure {
  std::string name, svg, caption;
};

std::vector<StudyFigure> studyFigures(const Study& s, const RankTests& t, const AnalysisOptions& options,
                                      const std::vector<PerceptualSeries>& series) {
  MaterialTable table{s.materials, modelStyles(s), s.rrmse, s.flip, s.e1, s.e2};
  std::vector<StudyFigure> figures = {
      {"error_curves", errorCurvesSvg(table, options.referenceModel), errorCurvesCaption(table, options.referenceModel)},
      {"heat_map", heatMapSvg(table), heatMapCaption()},
  };
  std::vector<CdModel> cd;
  if (t.friedman)
    for (std::size_t k : t.rankOrder) cd.push_back({s.models[k], t.friedman->meanRanks[k]});
  std::string test = t.methods.empty() ? std::string("no Wilcoxon test") : *t.methods.begin();
  if (t.methods.size() > 1) test = "exact or normal approximation";
  figures.push_back({"critical_difference", criticalDifferenceSvg(cd, t.cliques, int(t.complete.size()), test),
                     criticalDifferenceCaption(int(t.complete.size()), test)});
  figures.push_back({"brdf_vs_image", brdfVsImageSvg(table), brdfVsImageCaption()});
  if (!options.perceptualDir.empty())
    figures.push_back({"perceptual", perceptualSvg(series, {"rRMSE r*", "ꟻLIP", "E1", "E2"}), perceptualCaption()});
  return figures;
}

// summary.md: the summary, the lighting table, where every other output is, the figures' captions and the
// methods.
std::string summaryMarkdown(const std::string& summary, const std::string& lightingMarkdown, const std::vector<StudyFigure>& figures,
                            const Json& results, bool peopleTex, const AnalysisOptions& options) {
  const bool studyFile = options.provenance && !options.provenance->studyText.empty();
  std::string md = "# Study summary\n\n```\n" + summary + "```\n\n" + lightingMarkdown +
                   "\nEvery statistic with its interval: `results.json`; "
                   "the rows: `rows.csv`, `rows.json`; per-model tables: `models.tex`; per-lighting table: `lighting.tex`; "
                   "methods: `methods.tex`" + std::string(peopleTex ? "; against people: `people.tex`" : "") +
                   std::string(studyFile ? "; the study file: `study.toml`" : "") + "; figures: ";
  for (std::size_t i = 0; i < figures.size(); ++i) md += (i ? ", " : "") + std::string("`") + figures[i].name + ".svg`";
  md += ".\n\n## Figures\n\n";
  for (const StudyFigure& f : figures) {
    std::string text;  // "r*" is not Markdown's emphasis
    for (char c : f.caption) text += c == '*' ? std::string("\\*") : std::string(1, c);
    md += "- `" + f.name + ".svg`: " + text + "\n";
  }
  if (!options.perceptualDir.empty())
    md += "\nPerceived distances: Lavoué, Bonneel, Farrugia, Soler, \"Perceptual quality of BRDF approximations: dataset and "
          "metrics\", Computer Graphics Forum 40(2), 2021.\n";
  md += "\n## Methods\n\n" + methodsMarkdown(results);
  return md;
}

// The analysis's files in `folder`, in this order: the rows, each figure (and its PNG when rsvg-convert is
// installed), results.json with the figures' list, the LaTeX (people.tex with perceptual data), the study
// file and summary.md.
AnalysisResult writeAnalysis(const std::filesystem::path& folder, const Study& s, const std::string& summary, Json& results,
                             const std::vector<StudyFigure>& figures, const LightingAnalysis& lighting, const PeopleAnalysis& people,
                             const AnalysisOptions& options) {
  AnalysisResult result;
  result.summary = summary;
  auto write = [&](const std::string& name, const std::string& contents) {
    writeFileAtomically(folder / name, contents);
    result.files.emplace_back(name);
  };
  const auto dump = [](const Json& j) { return j.dump(2, ' ', false, Json::error_handler_t::replace) + "\n"; };
  write("rows.csv", rowsCsv(s.all));
  write("rows.json", dump(rowsJson(s.all)));
  Json figureList = Json::array();
  const auto rsvg = plot::findRsvgConvert();
  for (const StudyFigure& f : figures) {
    write(f.name + ".svg", f.svg);
    if (rsvg) {
      plot::svgToPng(*rsvg, folder / (f.name + ".svg"), folder / (f.name + ".png"), 1.5);
      result.files.emplace_back(f.name + ".png");
    }
    figureList.push_back({{"name", f.name}, {"svg", f.name + ".svg"}, {"png", rsvg ? Json(f.name + ".png") : Json(nullptr)}, {"caption", f.caption}});
  }
  results["figures"] = figureList;
  write("results.json", dump(results));
  write("models.tex", modelsTex(results));
  write("lighting.tex", lighting.tex);
  write("methods.tex", methodsTex(results));
  if (!people.tex.empty()) write("people.tex", people.tex);
  // The study file as it was read: the settings of these results, beside them.
  if (options.provenance && !options.provenance->studyText.empty()) write(kStudyFileCopy, options.provenance->studyText);
  write("summary.md", summaryMarkdown(summary, lighting.markdown + (people.markdown.empty() ? "" : "\n" + people.markdown), figures,
                                      results, !people.tex.empty(), options));
  return result;
}
}  // namespace

double expectedAnalysisSeconds(int resamples, std::size_t materials, std::size_t models) {
  constexpr double kSecondsPerUnit = 25.0 / (2000.0 * 100.0 * 36.0);
  return kSecondsPerUnit * double(resamples) * double(materials) * double(models) * double(models);
}

AnalysisResult analyseStudy(std::span<const StudyRow> rows, const AnalysisOptions& options, const std::filesystem::path& folder) {
  if (options.resamples < 0 || options.resamples > 1000000)
    throw InputError("study: bootstrap resamples " + std::to_string(options.resamples) + " outside 0 … 1000000");
  constexpr int kSteps = 6;
  const auto step = [&](int k, const std::string& what) {
    if (options.progress) options.progress(k, kSteps, what);
  };
  step(1, "rows, verdicts and rank tests");
  // The perceptual data are read first: a malformed table stops the analysis before anything is written.
  if (!options.perceptualDir.empty()) (void)PerceptualData::read(options.perceptualDir);
  const Study s = readRows(rows);
  const RankTests t = rankTests(s);
  const VerdictCounts verdicts = verdictCounts(s);
  Json results;
  results["generator"] = "glossy study";
  results["glossy"] = glossyJson();
  if (options.provenance) results["provenance"] = provenanceJson(*options.provenance);
  else results["provenance"] = Json{{"reason", "the rows were analysed without their study file"}};
  results["fits"] = fitsJson(s.all);
  results["seed"] = options.seed;
  results["resamples"] = options.resamples;
  results["interval"] = "95 % percentile bootstrap, materials resampled with their sheets";
  results["counts"] = countsJson(s, verdicts);
  results["renderNoise"] = renderNoiseJson(s);
  results["materials"] = perMaterial(s);

  step(2, "per-model and per-lighting intervals");
  std::vector<Interval> meanIv;
  results["models"] = perModel(s, t, options, meanIv);
  addRankTests(s, t, results);
  std::vector<std::string> rankOrder;
  for (std::size_t k : t.rankOrder) rankOrder.push_back(s.models[k]);
  const LightingAnalysis lighting = analyseLighting(s.used, rankOrder, options.resamples, options.seed);
  results["lighting"] = lighting.json;

  step(3, "pairwise shares of materials");
  results["closerThan"] = closerThan(s, options);

  step(4, "BRDF-space against image error");
  std::string claimHeadline, peopleHeadline;
  Json differences = Json::array();
  results["brdfVsImage"] = brdfVsImage(s, options, differences, claimHeadline);
  results["e2MinusE1"] = differences;

  step(5, "against people");
  std::vector<PerceptualSeries> series;
  results["againstPeople"] = againstPeople(s, options, peopleHeadline, series);
  PeopleAnalysis within;
  if (!options.perceptualDir.empty()) {
    within = closestToPeople(s.used, PerceptualData::read(options.perceptualDir), options.resamples, options.seed);
    results["againstPeople"]["withinMaterial"] = within.json;
    peopleHeadline += (peopleHeadline.empty() ? "" : "\n") + within.headline;
    if (!peopleHeadline.empty() && peopleHeadline.back() == '\n') peopleHeadline.pop_back();
  }
  const std::string summary = summaryText(s, t, verdicts, results, lighting.headline, claimHeadline, peopleHeadline);
  results["summary"] = summary;

  step(6, "figures and files");
  const std::vector<StudyFigure> figures = studyFigures(s, t, options, series);
  return writeAnalysis(folder, s, summary, results, figures, lighting, within, options);
}

}  // namespace glossy::study
