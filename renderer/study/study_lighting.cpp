// The study's lighting outputs (study_lighting.h). As everywhere in the study, materials are the sampling
// unit: under one lighting a material's r* of a model is the mean over its scenes, and the lightings of one
// material are compared with each other, never pooled as if they were more materials.
#include "renderer/study/study_lighting.h"

#include "materials/core/text.h"
#include "renderer/study/study_intervals.h"
#include "renderer/study/study_statistics.h"
#include "renderer/study/study_tables.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <iterator>

namespace glossy::study {

namespace {

using Json = nlohmann::ordered_json;
using Opt = std::optional<double>;

Json num(const Opt& v) { return v ? Json(*v) : Json(nullptr); }

struct SheetKey {
  std::string material, scene, lighting;
  auto operator<=>(const SheetKey&) const = default;
};

struct Data {
  std::vector<std::string> lightings, materials, models;
  std::map<SheetKey, std::map<std::size_t, const StudyRow*>> sheets;  // model index → row
  std::vector<std::vector<std::vector<Opt>>> rrmse;                   // [lighting][material][model]
};

Data readData(const std::vector<const StudyRow*>& rows, const std::vector<std::string>& models) {
  Data d;
  d.models = models;
  std::map<std::string, std::size_t> modelIndex;
  for (std::size_t k = 0; k < models.size(); ++k) modelIndex.emplace(models[k], k);
  std::set<std::string> lightings, materials;
  for (const StudyRow* r : rows) {
    const auto k = modelIndex.find(r->label);
    if (!r->rrmse || k == modelIndex.end()) continue;
    d.sheets[{r->material, r->scene, r->lighting}][k->second] = r;
    lightings.insert(r->lighting);
    materials.insert(r->material);
  }
  d.lightings.assign(lightings.begin(), lightings.end());
  d.materials.assign(materials.begin(), materials.end());
  d.rrmse.assign(d.lightings.size(), std::vector<std::vector<Opt>>(d.materials.size(), std::vector<Opt>(models.size())));
  for (std::size_t l = 0; l < d.lightings.size(); ++l)
    for (std::size_t i = 0; i < d.materials.size(); ++i)
      for (std::size_t k = 0; k < models.size(); ++k) {
        std::vector<double> v;
        for (const auto& [key, sheet] : d.sheets)
          if (key.material == d.materials[i] && key.lighting == d.lightings[l])
            if (const auto it = sheet.find(k); it != sheet.end()) v.push_back(*it->second->rrmse);
        d.rrmse[l][i][k] = meanOf(v);
      }
  return d;
}

// A material's ranks of the models (1 = lowest r*), ties given their mean rank.
std::vector<double> ranksOf(const std::vector<Opt>& values) {
  std::vector<double> v;
  for (const Opt& x : values) v.push_back(*x);
  return averageRanks(v);
}

bool complete(const std::vector<Opt>& values) {
  return std::all_of(values.begin(), values.end(), [](const Opt& v) { return v.has_value(); });
}

// ---- each lighting on its own ------------------------------------------------------------------------------

struct LightingTable {
  std::string lighting;
  int sheets = 0;
  std::vector<std::size_t> complete;  // materials with every model under this lighting
  std::vector<Opt> meanRank;
  std::vector<int> sheetsOf, closest, tied;
  std::vector<Interval> median;
  std::optional<FriedmanResult> friedman;
  std::string friedmanReason;
  std::optional<std::pair<std::size_t, std::size_t>> top;  // the two best-ranked models
  std::optional<WilcoxonResult> topTest;
  std::string topReason;
};

LightingTable lightingTable(const Data& d, std::size_t l, int resamples, std::uint64_t seed) {
  LightingTable t;
  t.lighting = d.lightings[l];
  const std::size_t nk = d.models.size();
  t.sheetsOf.assign(nk, 0);
  t.closest.assign(nk, 0);
  t.tied.assign(nk, 0);
  for (const auto& [key, sheet] : d.sheets) {
    if (key.lighting != t.lighting) continue;
    ++t.sheets;
    for (const auto& [k, row] : sheet) {
      ++t.sheetsOf[k];
      t.closest[k] += row->closest ? 1 : 0;
      t.tied[k] += row->tied ? 1 : 0;
    }
  }
  std::vector<std::vector<double>> blocks;
  for (std::size_t i = 0; i < d.materials.size(); ++i)
    if (complete(d.rrmse[l][i])) {
      t.complete.push_back(i);
      std::vector<double> b;
      for (const Opt& v : d.rrmse[l][i]) b.push_back(*v);
      blocks.push_back(b);
    }
  t.meanRank.assign(nk, std::nullopt);
  if (!blocks.empty() && nk >= 2) {
    std::vector<double> sum(nk, 0.0);
    for (std::size_t i : t.complete) {
      const auto r = ranksOf(d.rrmse[l][i]);
      for (std::size_t k = 0; k < nk; ++k) sum[k] += r[k];
    }
    for (std::size_t k = 0; k < nk; ++k) t.meanRank[k] = sum[k] / double(t.complete.size());
  }
  if (nk < 2) {
    t.friedmanReason = t.topReason = "fewer than 2 models";
  } else if (blocks.size() < kTestMinMaterials) {
    t.friedmanReason = t.topReason = tooFewForTest(blocks.size());
  } else {
    t.friedman = friedman(blocks);
    if (!t.friedman) t.friedmanReason = "every material ties every model";
  }
  if (nk >= 2 && t.meanRank[0]) {
    std::vector<std::size_t> order(nk);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return *t.meanRank[a] < *t.meanRank[b]; });
    t.top = std::pair(order[0], order[1]);
    if (t.topReason.empty()) {
      std::vector<double> x, y;
      for (const auto& b : blocks) {
        x.push_back(b[order[0]]);
        y.push_back(b[order[1]]);
      }
      t.topTest = wilcoxonSignedRank(x, y, &t.topReason);
    }
  }
  for (std::size_t k = 0; k < nk; ++k) {
    std::vector<std::size_t> have;
    for (std::size_t i = 0; i < d.materials.size(); ++i)
      if (d.rrmse[l][i][k]) have.push_back(i);
    t.median.push_back(materialInterval(
        have.size(),
        [&](const std::vector<std::size_t>& idx) {
          std::vector<double> v;
          for (std::size_t i : idx) v.push_back(*d.rrmse[l][have[i]][k]);
          return medianOf(v);
        },
        resamples, seedFor(seed, "lighting/" + t.lighting + "/median/" + d.models[k])));
  }
  return t;
}

Json tableJson(const Data& d, const LightingTable& t) {
  Json j;
  j["lighting"] = t.lighting;
  j["sheets"] = t.sheets;
  j["materials"] = int(t.complete.size());
  j["materialsLeftOut"] = int(d.materials.size() - t.complete.size());
  Json models = Json::array();
  for (std::size_t k = 0; k < d.models.size(); ++k) {
    Json m;
    m["label"] = d.models[k];
    m["sheets"] = t.sheetsOf[k];
    m["closest"] = t.closest[k];
    m["tied"] = t.tied[k];
    m["meanRank"] = num(t.meanRank[k]);
    m["medianRrmse"] = intervalJson(t.median[k]);
    models.push_back(m);
  }
  j["models"] = models;
  j["friedman"] = friedmanJson(t.friedman, t.friedmanReason);
  Json p;
  p["a"] = t.top ? Json(d.models[t.top->first]) : Json(nullptr);
  p["b"] = t.top ? Json(d.models[t.top->second]) : Json(nullptr);
  p["test"] = "Wilcoxon signed-rank, two-sided, uncorrected (one test per lighting)";
  if (t.topTest) {
    p["n"] = t.topTest->n;
    p["zeros"] = t.topTest->zeros;
    p["statistic"] = t.topTest->statistic;
    p["p"] = t.topTest->p;
    p["method"] = t.topTest->method;
  } else {
    p["p"] = nullptr;
    p["reason"] = t.top ? t.topReason : std::string("no mean ranks (no material has every model)");
  }
  j["topPair"] = p;
  return j;
}

// ---- agreement across lightings --------------------------------------------------------------------------

struct Agreement {
  std::vector<Opt> perMaterial;  // Kendall's W of the material's lightings (raters) over its models
  int defined = 0;
  Interval mean;
  Opt median;
  std::vector<std::size_t> everywhere;  // materials with every model under every lighting
  Interval ofMeanRanks;
  std::string reason;  // why there is nothing to compare, "" otherwise
};

Agreement agreement(const Data& d, int resamples, std::uint64_t seed) {
  Agreement a;
  a.perMaterial.assign(d.materials.size(), std::nullopt);
  if (d.lightings.size() < 2) {
    a.reason = d.lightings.empty() ? "no lighting has rows with r*" : "one lighting: nothing to compare";
    return a;
  }
  std::vector<double> defined;
  for (std::size_t i = 0; i < d.materials.size(); ++i) {
    std::vector<std::size_t> ls;
    for (std::size_t l = 0; l < d.lightings.size(); ++l)
      if (std::any_of(d.rrmse[l][i].begin(), d.rrmse[l][i].end(), [](const Opt& v) { return v.has_value(); })) ls.push_back(l);
    std::vector<std::vector<double>> scores(ls.size());
    for (std::size_t k = 0; k < d.models.size(); ++k)
      if (std::all_of(ls.begin(), ls.end(), [&](std::size_t l) { return d.rrmse[l][i][k].has_value(); }))
        for (std::size_t r = 0; r < ls.size(); ++r) scores[r].push_back(*d.rrmse[ls[r]][i][k]);
    a.perMaterial[i] = kendallW(scores);
    if (a.perMaterial[i]) defined.push_back(*a.perMaterial[i]);
  }
  a.defined = int(defined.size());
  a.median = medianOf(defined);
  a.mean = materialInterval(
      d.materials.size(),
      [&](const std::vector<std::size_t>& idx) {
        std::vector<double> v;
        for (std::size_t i : idx)
          if (a.perMaterial[i]) v.push_back(*a.perMaterial[i]);
        return meanOf(v);
      },
      resamples, seedFor(seed, "lighting/kendallW/mean"), defined.size());
  for (std::size_t i = 0; i < d.materials.size(); ++i)
    if (std::all_of(d.rrmse.begin(), d.rrmse.end(), [&](const auto& byMaterial) { return complete(byMaterial[i]); }))
      a.everywhere.push_back(i);
  // Each lighting's mean ranks over the drawn materials are one rater's scores of the models.
  a.ofMeanRanks = materialInterval(
      a.everywhere.size(),
      [&](const std::vector<std::size_t>& idx) -> Opt {
        std::vector<std::vector<double>> rows(d.lightings.size(), std::vector<double>(d.models.size(), 0.0));
        for (std::size_t l = 0; l < d.lightings.size(); ++l)
          for (std::size_t j : idx) {
            const auto r = ranksOf(d.rrmse[l][a.everywhere[j]]);
            for (std::size_t k = 0; k < r.size(); ++k) rows[l][k] += r[k] / double(idx.size());
          }
        return kendallW(rows);
      },
      resamples, seedFor(seed, "lighting/kendallW/meanRanks"));
  return a;
}

Json kendallWJson(const Data& d, const Agreement& a) {
  Json w;
  w["what"] = "Kendall's W of rankings of the models by r* under the lightings (1: every lighting ranks them alike, 0: no agreement)";
  Json wm = intervalJson(a.mean);
  wm["what"] = "each material's W (raters: its lightings, r* averaged over scenes; items: the models under all of them), mean over materials";
  wm["materials"] = a.defined;
  wm["materialsUndefined"] = int(d.materials.size()) - a.defined;
  wm["median"] = num(a.median);
  w["meanOverMaterials"] = wm;
  Json wr = intervalJson(a.ofMeanRanks);
  wr["what"] = "W of the lightings' mean ranks of the models, over the materials with every model under every lighting";
  wr["materials"] = int(a.everywhere.size());
  w["ofMeanRanks"] = wr;
  if (!a.reason.empty()) w["reason"] = a.reason;
  return w;
}

// ---- verdicts that change with the lighting ---------------------------------------------------------------

struct SheetVerdict {
  std::string scene, lighting;
  std::vector<std::string> named;  // the closest model, or the tied ones; empty: no verdict
  bool closest = false;
  std::string lowest;              // the model with the lowest r* (first label on an exact tie)
};

std::string verdictText(const SheetVerdict& v) {
  if (v.named.empty()) return "none";
  return v.closest ? v.named[0] : "tie: " + joined(v.named, ", ");
}

struct Changes {
  std::vector<std::string> verdictChanged, lowestChanged;
  int withVerdicts = 0, withSheets = 0;  // materials with two lightings or more to compare (in one scene)
  std::map<std::string, std::vector<SheetVerdict>> sheets;  // per material
};

Changes changes(const Data& d) {
  Changes c;
  for (const auto& [key, sheet] : d.sheets) {
    SheetVerdict v{key.scene, key.lighting, {}, false, {}};
    double best = 0.0;
    for (const auto& [k, row] : sheet) {
      if (row->closest) {
        v.named = {d.models[k]};
        v.closest = true;
      }
      if (row->tied && !v.closest) v.named.push_back(d.models[k]);
      if (v.lowest.empty() || *row->rrmse < best || (*row->rrmse == best && d.models[k] < v.lowest)) {
        best = *row->rrmse;
        v.lowest = d.models[k];
      }
    }
    std::sort(v.named.begin(), v.named.end());
    c.sheets[key.material].push_back(v);
  }
  for (const auto& [material, sheets] : c.sheets) {
    bool verdictCompared = false, lowestCompared = false, verdictChanged = false, lowestChanged = false;
    std::set<std::string> scenes;
    for (const SheetVerdict& v : sheets) scenes.insert(v.scene);
    for (const std::string& scene : scenes) {
      std::vector<const SheetVerdict*> decided, all;
      for (const SheetVerdict& v : sheets)
        if (v.scene == scene) {
          all.push_back(&v);
          if (!v.named.empty()) decided.push_back(&v);
        }
      lowestCompared |= all.size() >= 2;
      verdictCompared |= decided.size() >= 2;
      for (const SheetVerdict* a : all)
        for (const SheetVerdict* b : all) {
          lowestChanged |= a->lowest != b->lowest;
          // A change is two verdicts that name no model in common: "A" against "B", or "A" against a tie of
          // B and C; "A" against a tie of A and B is a verdict the noise left open, not a contradiction.
          if (a->named.empty() || b->named.empty()) continue;
          std::vector<std::string> common;
          std::set_intersection(a->named.begin(), a->named.end(), b->named.begin(), b->named.end(), std::back_inserter(common));
          verdictChanged |= common.empty();
        }
    }
    c.withVerdicts += verdictCompared ? 1 : 0;
    c.withSheets += lowestCompared ? 1 : 0;
    if (verdictChanged) c.verdictChanged.push_back(material);
    if (lowestChanged) c.lowestChanged.push_back(material);
  }
  return c;
}

// One change list: the `changed` materials with each sheet's verdict (`verdicts`) or lowest-r* model, out of
// the `compared` materials.
Json changesJson(const Changes& c, const std::vector<std::string>& changed, int compared, bool verdicts, const char* what) {
  Json x;
  x["what"] = what;
  x["materials"] = compared;
  x["changed"] = int(changed.size());
  Json list = Json::array();
  for (const std::string& m : changed) {
    Json e;
    e["material"] = m;
    Json sheets = Json::array();
    for (const SheetVerdict& v : c.sheets.at(m)) {
      Json s;
      s["scene"] = v.scene;
      s["lighting"] = v.lighting;
      if (verdicts) {
        s["verdict"] = v.named.empty() ? "none" : (v.closest ? "closest" : "tie");
        s["models"] = v.named;
      } else {
        s["lowest"] = v.lowest;
      }
      sheets.push_back(s);
    }
    e["sheets"] = sheets;
    list.push_back(e);
  }
  x["list"] = list;
  return x;
}

// ---- text --------------------------------------------------------------------------------------------------

// Text as LaTeX shows it; latexEscape writes the "≥" of the small-sample reasons as math.
std::string texText(const std::string& text) { return latexEscape(text); }

std::string pText(double p) { return formatted("%.3g", p); }

// "p = 2.1e-05" as LaTeX: $p = 2.1\times10^{-5}$.
std::string pTex(double p) {
  std::string s = formatted("%.2g", p);
  const auto e = s.find('e');
  if (e == std::string::npos) return "$p = " + s + "$";
  const int exponent = std::stoi(s.substr(e + 1));
  return "$p = " + s.substr(0, e) + "\\times10^{" + std::to_string(exponent) + "}$";
}

std::string rankText(const Opt& r) { return r ? formatted("%.2f", *r) : std::string("--"); }

std::string materialsText(std::size_t n) { return std::to_string(n) + (n == 1 ? " material" : " materials"); }

std::string friedmanText(const LightingTable& t) {
  if (!t.friedman) return "Friedman test: none (" + t.friedmanReason + ")";
  return formatted("Friedman \xCF\x87\xC2\xB2 = %.2f (df %d), p = ", t.friedman->chiSquare, t.friedman->treatments - 1) +
         pText(t.friedman->pChiSquare);
}

std::string topPairText(const Data& d, const LightingTable& t) {
  if (!t.top) return "no two models to compare";
  std::string s = "the two best-ranked, " + d.models[t.top->first] + " and " + d.models[t.top->second] + ": ";
  if (!t.topTest) return s + "no test (" + t.topReason + ")";
  return s + "Wilcoxon signed-rank p = " + pText(t.topTest->p) + " (" + (t.topTest->method == "exact" ? "exact" : "normal approximation") +
         ", " + std::to_string(t.topTest->n) + " non-zero differences, uncorrected)";
}

std::string changedList(const Changes& c, const std::vector<std::string>& materials, bool verdicts) {
  return joined(materials, "; ", [&](const std::string& m) {
    const auto& sheets = c.sheets.at(m);
    // The scene is named only where the material has more than one.
    const bool scenes = std::any_of(sheets.begin(), sheets.end(), [&](const SheetVerdict& v) { return v.scene != sheets[0].scene; });
    return m + " (" + joined(sheets, ", ", [&](const SheetVerdict& v) {
             return (scenes ? v.scene + "/" : std::string()) + v.lighting + ": " + (verdicts ? verdictText(v) : v.lowest);
           }) + ")";
  });
}

// ---- results.json's object, the summary's paragraph and section, lighting.tex -----------------------------

// results.json's "lighting".
Json resultsJson(const Data& d, const std::vector<LightingTable>& tables, const Agreement& a, const Changes& c) {
  Json j;
  j["lightings"] = d.lightings;
  j["materials"] = int(d.materials.size());
  Json per = Json::array();
  for (const LightingTable& t : tables) per.push_back(tableJson(d, t));
  j["perLighting"] = per;
  j["kendallW"] = kendallWJson(d, a);
  j["verdictChanges"] = changesJson(c, c.verdictChanged, c.withVerdicts, true,
                                    "materials two of whose lightings (in one scene) have verdicts naming no model in common; of the "
                                    "materials with a verdict under two lightings or more");
  j["lowestRrmseChanges"] = changesJson(c, c.lowestChanged, c.withSheets, false,
                                        "materials whose lowest-r* model differs between two lightings (in one scene), render noise "
                                        "not considered");
  return j;
}

// The printed summary's paragraph.
std::string headline(const Data& d, const std::vector<LightingTable>& tables, const Agreement& a, const Changes& c) {
  std::string h = "Lighting (" + std::to_string(d.lightings.size()) + "): ";
  for (std::size_t l = 0; l < tables.size(); ++l) {
    const LightingTable& t = tables[l];
    h += (l ? "; " : "") + t.lighting + ": best-ranked " + (t.top ? d.models[t.top->first] : std::string("none")) + ", " +
         (t.friedman ? "Friedman p = " + pText(t.friedman->pChiSquare) : "no Friedman test (" + t.friedmanReason + ")");
  }
  h += tables.empty() ? "none (no rows with r*).\n" : ".\n";
  if (a.reason.empty()) {
    h += "  Kendall's W across lightings, mean over materials: " + intervalText(a.mean, "%.3f") + "; the closest model changes with the lighting for " +
         std::to_string(c.verdictChanged.size()) + " of " + std::to_string(c.withVerdicts) +
         " materials with a verdict under two lightings (lowest r* changes: " + std::to_string(c.lowestChanged.size()) + " of " +
         std::to_string(c.withSheets) + ").\n";
  }
  return h;
}

// summary.md's section.
std::string markdownSection(const Data& d, const std::vector<LightingTable>& tables, const Agreement& a, const Changes& c) {
  std::string md = "## Lighting\n\nEach lighting on its own, over the materials with every model under it (a material's r* under a lighting "
                   "is the mean over its scenes): the models' mean rank of r* (1 = closest), their median r* with its 95 % bootstrap interval "
                   "over materials, and the sheets whose verdict names them closest or tied.\n";
  for (const LightingTable& t : tables) {
    md += "\n### " + t.lighting + ": " + materialsText(t.complete.size()) + ", " + std::to_string(t.sheets) + " sheets\n\n";
    md += "| model | mean rank | median r* [95 %] | closest | tied |\n|---|---|---|---|---|\n";
    for (std::size_t k = 0; k < d.models.size(); ++k)
      md += "| " + d.models[k] + " | " + rankText(t.meanRank[k]) + " | " + intervalText(t.median[k], "%.4f") + " | " +
            std::to_string(t.closest[k]) + " | " + std::to_string(t.tied[k]) + " |\n";
    md += "\n" + friedmanText(t) + "; " + topPairText(d, t) + ".\n";
  }
  md += "\n### Across lightings\n\n";
  if (!a.reason.empty()) {
    md += "None: " + a.reason + ".\n";
  } else {
    md += "- Kendall's W of each material's ranking of the models under its lightings (1: every lighting ranks them alike): mean " +
          intervalText(a.mean, "%.3f") + " over " + materialsText(std::size_t(a.defined)) +
          (a.median ? formatted(" (median %.3f)", *a.median) : std::string()) + ".\n";
    md += "- Kendall's W of the lightings' mean ranks, over the " + materialsText(a.everywhere.size()) +
          " with every model under every lighting: " + intervalText(a.ofMeanRanks, "%.3f") + ".\n";
    md += "- The closest model changes with the lighting (two lightings' verdicts name no model in common) for " +
          std::to_string(c.verdictChanged.size()) + " of " + materialsText(std::size_t(c.withVerdicts)) +
          " with a verdict under two lightings or more" + (c.verdictChanged.empty() ? "" : ": " + changedList(c, c.verdictChanged, true)) + ".\n";
    md += "- The lowest r* changes with the lighting (point estimates, render noise not considered) for " +
          std::to_string(c.lowestChanged.size()) + " of " + materialsText(std::size_t(c.withSheets)) +
          (c.lowestChanged.empty() ? "" : ": " + changedList(c, c.lowestChanged, false)) + ".\n";
  }
  return md;
}

// lighting.tex: plain LaTeX (no package), so it compiles in any paper.
std::string lightingTex(const Data& d, const std::vector<LightingTable>& tables, const Agreement& a, const Changes& c) {
  bool intervalAbsent = false;
  for (const LightingTable& t : tables)
    for (const Interval& iv : t.median) intervalAbsent |= iv.estimate && !iv.lo;
  std::string caption = "The models under each lighting: mean rank of the relative RMSE $r^*$ (1 = closest) over the materials "
                        "with every model under the lighting, median $r^*$ with its 95\\,\\% percentile bootstrap interval over "
                        "materials, and the sheets whose verdict names the model closest. Per lighting: Friedman's test, and "
                        "Wilcoxon's signed-rank test of the two best-ranked models (uncorrected).";
  if (intervalAbsent) caption += " An interval is absent where fewer than " + std::to_string(kIntervalMinMaterials) + " materials carry it.";
  if (a.reason.empty()) {
    caption += " Across lightings, Kendall's $W$ of each material's rankings averages " + texText(intervalText(a.mean, "%.3f")) +
               "; the closest model changes with the lighting for " + std::to_string(c.verdictChanged.size()) + " of " +
               materialsText(std::size_t(c.withVerdicts)) + " with a verdict under two lightings or more.";
  }
  std::string tex = "% glossy study: the models under each lighting (plain LaTeX, no package needed).\n"
                    "\\begin{table}[htbp]\n\\centering\n\\caption{" + caption + "}\n\\label{tab:glossy-study-lighting}\n"
                    "\\begin{tabular}{llrlr}\n\\hline\n"
                    "Lighting & Model & Mean rank & Median $r^*$ [95\\,\\% CI] & Closest \\\\\n\\hline\n";
  std::string testLines;
  for (const LightingTable& t : tables) {
    for (std::size_t k = 0; k < d.models.size(); ++k)
      tex += (k == 0 ? latexEscape(t.lighting) + " (" + std::to_string(t.complete.size()) + ")" : std::string()) + " & " +
             latexEscape(d.models[k]) + " & " + rankText(t.meanRank[k]) + " & " + intervalCell(intervalJson(t.median[k])) + " & " +
             std::to_string(t.closest[k]) + " \\\\\n";
    std::string tests = t.friedman ? formatted("Friedman $\\chi^2 = %.2f$ (df %d), ", t.friedman->chiSquare, t.friedman->treatments - 1) +
                                         pTex(t.friedman->pChiSquare)
                                   : "Friedman: " + texText(t.friedmanReason);
    if (t.top)
      tests += "; " + latexEscape(d.models[t.top->first]) + " vs.\\ " + latexEscape(d.models[t.top->second]) + ": " +
               (t.topTest ? "Wilcoxon " + pTex(t.topTest->p) : "no test (" + texText(t.topReason) + ")");
    tex += "\\hline\n";
    testLines += "\\emph{" + latexEscape(t.lighting) + "}: " + tests + ".\\par\n";
  }
  // The tests below the table, as paragraphs: their reasons may be longer than a column can hold.
  tex += "\\end{tabular}\n\\par\\smallskip\n{\\footnotesize\n" + testLines + "}\n\\end{table}\n";
  return tex;
}

}  // namespace

LightingAnalysis analyseLighting(const std::vector<const StudyRow*>& rows, const std::vector<std::string>& models,
                                 int resamples, std::uint64_t seed) {
  const Data d = readData(rows, models);
  std::vector<LightingTable> tables;
  for (std::size_t l = 0; l < d.lightings.size(); ++l) tables.push_back(lightingTable(d, l, resamples, seed));
  const Agreement a = agreement(d, resamples, seed);
  const Changes c = changes(d);
  return {resultsJson(d, tables, a, c), headline(d, tables, a, c), markdownSection(d, tables, a, c), lightingTex(d, tables, a, c)};
}

}  // namespace glossy::study
