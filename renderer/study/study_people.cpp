#include "renderer/study/study_people.h"

#include "materials/core/text.h"
#include "renderer/study/study_intervals.h"
#include "renderer/study/study_statistics.h"
#include "renderer/study/study_tables.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>

namespace glossy::study {

namespace {

using Json = nlohmann::ordered_json;
using Opt = std::optional<double>;

constexpr const char* kFigures[] = {"rrmse", "flip", "deltaEItp", "ssim", "e1", "e2"};
constexpr std::size_t kFigureCount = std::size(kFigures);
// The figures as the summary's and people.tex's tables name them, in kFigures' order.
constexpr const char* kMarkdownNames[] = {"r\\*", "ꟻLIP", "ΔE_ITP", "1 − SSIM", "E1", "E2"};
constexpr const char* kTexNames[] = {"$r^*$", "FLIP", "$\\Delta E_{\\mathrm{ITP}}$", "$1 - \\mathrm{SSIM}$", "E1", "E2"};
static_assert(std::size(kMarkdownNames) == kFigureCount && std::size(kTexNames) == kFigureCount);

// Each figure as a distance, smaller closer: SSIM (a similarity) as 1 − SSIM.
Opt figureOf(const StudyRow& r, std::size_t f) {
  const Opt values[] = {r.rrmse, r.flip, r.deltaEItp, r.ssim ? Opt(1.0 - *r.ssim) : std::nullopt, r.e1, r.e2};
  return values[f];
}

// A material's approximations side by side: for each, every figure (the mean over the rows given) and
// people's distance.
struct MaterialTable {
  std::vector<std::array<Opt, kFigureCount>> figure;
  std::vector<Opt> distance;
};

std::map<std::string, MaterialTable> tablesOf(const std::vector<const StudyRow*>& rows, const PerceptualData& data,
                                              const std::vector<PerceptualFit>& approximations, const std::string& lighting) {
  std::map<std::string, std::vector<std::array<std::vector<double>, kFigureCount>>> values;
  for (const StudyRow* r : rows) {
    if (!lighting.empty() && r->lighting != lighting) continue;
    for (std::size_t a = 0; a < approximations.size(); ++a) {
      if (r->fit != approximations[a].fit || r->fitSource != approximations[a].fitSource) continue;
      auto& v = values[r->material];
      v.resize(approximations.size());
      for (std::size_t f = 0; f < kFigureCount; ++f)
        if (const Opt x = figureOf(*r, f)) v[a][f].push_back(*x);
    }
  }
  std::map<std::string, MaterialTable> tables;
  for (const auto& [material, v] : values) {
    MaterialTable& t = tables[material];
    for (std::size_t a = 0; a < approximations.size(); ++a) {
      std::array<Opt, kFigureCount> means;
      for (std::size_t f = 0; f < kFigureCount; ++f) means[f] = meanOf(v[a][f]);
      t.figure.push_back(means);
      t.distance.push_back(data.distance(approximations[a].method, material));
    }
  }
  return tables;
}

// The indices of the smallest values (exact ties kept).
std::vector<std::size_t> closest(const std::vector<double>& v) {
  const double lowest = *std::min_element(v.begin(), v.end());
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (v[i] == lowest) out.push_back(i);
  return out;
}

// One material's figure and distances, when it has both for every approximation.
struct Pair {
  std::vector<double> figure, distance;
};

// One figure's three statistics over the materials that have it and a distance for every approximation.
struct FigureAgreement {
  const char* figure;
  std::size_t materials = 0;
  Interval rho, tau, share;
};

std::vector<FigureAgreement> agreements(const std::map<std::string, MaterialTable>& tables, std::size_t approximations, int resamples,
                                        std::uint64_t seed, const std::string& key) {
  std::vector<FigureAgreement> out;
  for (std::size_t f = 0; f < kFigureCount; ++f) {
    std::vector<Pair> materials;
    for (const auto& [name, t] : tables) {
      Pair p;
      for (std::size_t a = 0; a < t.figure.size(); ++a)
        if (t.figure[a][f] && t.distance[a]) {
          p.figure.push_back(*t.figure[a][f]);
          p.distance.push_back(*t.distance[a]);
        }
      if (p.figure.size() == approximations) materials.push_back(std::move(p));
    }
    const auto pooled = [&](const std::vector<std::size_t>& idx) -> Opt {
      std::vector<double> x, y;
      for (std::size_t i : idx) {
        x.insert(x.end(), materials[i].figure.begin(), materials[i].figure.end());
        y.insert(y.end(), materials[i].distance.begin(), materials[i].distance.end());
      }
      return spearman(x, y);
    };
    const auto meanTau = [&](const std::vector<std::size_t>& idx) -> Opt {
      double sum = 0.0;
      int n = 0;
      for (std::size_t i : idx)
        if (const Opt tau = kendallTauB(materials[i].figure, materials[i].distance)) {
          sum += *tau;
          ++n;
        }
      return n ? Opt(sum / n) : std::nullopt;
    };
    const auto share = [&](const std::vector<std::size_t>& idx) -> Opt {
      if (idx.empty()) return std::nullopt;
      double sum = 0.0;
      for (std::size_t i : idx) {
        const auto g = closest(materials[i].figure), p = closest(materials[i].distance);
        std::size_t both = 0;
        for (std::size_t a : g) both += std::size_t(std::count(p.begin(), p.end(), a));
        sum += double(both) / double(g.size() * p.size());
      }
      return sum / double(idx.size());
    };
    const std::string k = "people-within/" + key + "/" + kFigures[f];
    out.push_back({kFigures[f], materials.size(), materialInterval(materials.size(), pooled, resamples, seedFor(seed, k + "/rho")),
                   materialInterval(materials.size(), meanTau, resamples, seedFor(seed, k + "/tau")),
                   materialInterval(materials.size(), share, resamples, seedFor(seed, k + "/closest"))});
  }
  return out;
}

// The figure whose closest approximation is most often people's (nullptr: none measured).
const FigureAgreement* bestOf(const std::vector<FigureAgreement>& all) {
  const FigureAgreement* best = nullptr;
  for (const FigureAgreement& a : all)
    if (a.share.estimate && (!best || *a.share.estimate > *best->share.estimate)) best = &a;
  return best;
}

Json agreementsJson(const std::vector<FigureAgreement>& all, std::size_t approximations) {
  Json out;
  Json figures = Json::array();
  for (const FigureAgreement& a : all)
    figures.push_back(Json{{"figure", a.figure},
                           {"materials", int(a.materials)},
                           {"pooledSpearman", intervalJson(a.rho)},
                           {"meanKendallTau", intervalJson(a.tau)},
                           {"closestAgrees", intervalJson(a.share)},
                           {"chance", Json{{"pooledSpearman", 0.0}, {"meanKendallTau", 0.0}, {"closestAgrees", 1.0 / double(approximations)}}}});
  out["figures"] = figures;
  const FigureAgreement* best = bestOf(all);
  out["agreesBest"] = best ? Json(best->figure) : Json(nullptr);
  return out;
}

// One ABC variant's results, as the summary's section and people.tex show them.
struct VariantTables {
  std::string abc;
  std::size_t approximations = 0;
  std::vector<FigureAgreement> overall;
  std::map<std::string, std::vector<FigureAgreement>> byLighting;
};

// What a variant without a single material to compare says instead of tables of nothing.
constexpr const char* kNoMaterial = "No material has a figure and a perceived distance for every approximation: the study's panels "
                                    "need every judged fit, as the grid lavoue2021 has them (scenes/studies/people.toml).";

std::string markdownOf(const VariantTables& v) {
  const std::size_t materials = v.overall.empty() ? 0 : v.overall.front().materials;
  if (materials == 0) return "### ABC as " + v.abc + "\n\n" + kNoMaterial + "\n";
  std::string md = "### ABC as " + v.abc + "\n\n" + std::to_string(materials) +
                   " materials with a figure and a perceived distance for every approximation; 95 % bootstrap intervals over "
                   "materials.\n\n| figure | people's closest named (chance " + formatted("%.2f", 1.0 / double(v.approximations)) +
                   ") | mean Kendall τ (chance 0) | pooled Spearman ρ (chance 0) |\n|---|---|---|---|\n";
  for (std::size_t f = 0; f < v.overall.size(); ++f)
    md += std::string("| ") + kMarkdownNames[f] + " | " + intervalText(v.overall[f].share, "%.2f") + " | " +
          intervalText(v.overall[f].tau, "%.2f") + " | " + intervalText(v.overall[f].rho, "%.2f") + " |\n";
  if (v.byLighting.empty()) return md;
  md += "\nPeople's closest named, under each lighting alone:\n\n| figure |";
  for (const auto& [lighting, _] : v.byLighting) md += " " + lighting + " |";
  md += "\n|---|";
  for (std::size_t i = 0; i < v.byLighting.size(); ++i) md += "---|";
  md += "\n";
  for (std::size_t f = 0; f < kFigureCount; ++f) {
    md += std::string("| ") + kMarkdownNames[f] + " |";
    for (const auto& [lighting, agreements] : v.byLighting) md.append(" ").append(intervalText(agreements[f].share, "%.2f")).append(" |");
    md += "\n";
  }
  return md;
}

// "" when no material has every figure: people.tex is then not written.
std::string texOf(const VariantTables& v) {
  const std::size_t materials = v.overall.empty() ? 0 : v.overall.front().materials;
  if (materials == 0) return "";
  std::string label = v.abc;
  std::replace(label.begin(), label.end(), ':', '-');
  std::string tex = "\\begin{table}[htbp]\n\\centering\n\\caption{Which approximation looks closest within a material: glossy's "
                    "figures against people's perceived distances (Lavou\\'e et al.\\ 2021), the approximations ABC as " +
                    latexEscape(v.abc) + ", Ngan et al.'s Ward, Blinn-Phong and Lafortune and Bagher et al.'s SGD; " +
                    std::to_string(materials) + " materials; 95\\,\\% bootstrap intervals over materials. Closest named: the "
                    "share of materials where the figure's closest is people's (chance " +
                    formatted("%.2f", 1.0 / double(v.approximations)) + "); chance is 0 for $\\tau$ and $\\rho$.}\n"
                    "\\label{tab:glossy-study-people-" + latexEscape(label) + "}\n\\begin{tabular}{llll}\n\\hline\n"
                    "Figure & closest named & mean Kendall $\\tau$ & pooled Spearman $\\rho$ \\\\\n\\hline\n";
  for (std::size_t f = 0; f < v.overall.size(); ++f)
    tex += std::string(kTexNames[f]) + " & " + latexEscape(intervalText(v.overall[f].share, "%.2f")) + " & " +
           latexEscape(intervalText(v.overall[f].tau, "%.2f")) + " & " + latexEscape(intervalText(v.overall[f].rho, "%.2f")) +
           " \\\\\n";
  tex += "\\hline\n\\end{tabular}\n";
  if (!v.byLighting.empty()) {
    tex += "\n\\medskip\nClosest named, under each lighting alone:\n\n\\begin{tabular}{l" + std::string(v.byLighting.size(), 'l') +
           "}\n\\hline\nFigure";
    for (const auto& [lighting, _] : v.byLighting) tex += " & " + latexEscape(lighting);
    tex += " \\\\\n\\hline\n";
    for (std::size_t f = 0; f < kFigureCount; ++f) {
      tex += kTexNames[f];
      for (const auto& [lighting, agreements] : v.byLighting) tex += " & " + latexEscape(intervalText(agreements[f].share, "%.2f"));
      tex += " \\\\\n";
    }
    tex += "\\hline\n\\end{tabular}\n";
  }
  return tex + "\\end{table}\n";
}

}  // namespace

PeopleAnalysis closestToPeople(const std::vector<const StudyRow*>& rows, const PerceptualData& data, int resamples,
                               std::uint64_t seed) {
  PeopleAnalysis out;
  Json& j = out.json;
  out.markdown = "## Against people: which approximation looks closest\n\nWithin a material, glossy's figures against the "
                 "distances people perceived (Lavoué et al. 2021) between each approximation and the measured material: Löw et "
                 "al.'s ABC (each of its two E2 fits in turn), Ngan et al.'s Ward, Blinn-Phong and Lafortune, Bagher et al.'s "
                 "SGD. Every figure is a distance here, smaller closer (SSIM as 1 − SSIM); a material's figure is the mean over "
                 "its sheets.\n\n";
  j["question"] = "within a material, which approximation looks closest: glossy's figures against people's";
  j["figuresAsDistances"] = "each figure smaller is closer: rrmse, flip, deltaEItp, e1, e2 as they are, ssim as 1 - SSIM";
  // What each dataset method's rows are taken to judge, with the evidence: how many materials the dataset
  // gives it for, and how many of the study's materials with the fit it covers.
  std::vector<PerceptualFit> shared = judgedApproximations();
  Json evidence = Json::array();
  std::set<std::string> lightings;
  for (const StudyRow* r : rows) lightings.insert(r->lighting);
  const auto evidenceOf = [&](const PerceptualFit& pf) {
    std::set<std::string> withFit;
    for (const StudyRow* r : rows)
      if (r->fit == pf.fit && r->fitSource == pf.fitSource) withFit.insert(r->material);
    std::size_t covered = 0;
    for (const std::string& m : withFit) covered += data.distance(pf.method, m) ? 1 : 0;
    return Json{{"method", pf.method}, {"fit", pf.fit}, {"fitSource", pf.fitSource},
                {"datasetMaterials", int(data.materialCount(pf.method))}, {"studyMaterialsWithFit", int(withFit.size())},
                {"ofThemJudged", int(covered)}};
  };
  for (const PerceptualFit& abc : perceptualFits()) evidence.push_back(evidenceOf(abc));
  for (const PerceptualFit& pf : shared) evidence.push_back(evidenceOf(pf));
  j["evidence"] = evidence;

  Json variants = Json::array();
  for (const PerceptualFit& abc : perceptualFits()) {
    std::vector<PerceptualFit> approximations = {abc};
    approximations.insert(approximations.end(), shared.begin(), shared.end());
    const std::size_t k = approximations.size();
    Json v;
    v["abc"] = abc.fit;
    v["approximations"] = joined(approximations, ", ", [](const PerceptualFit& p) { return p.method + " = " + p.fit; });
    VariantTables tables{abc.fit, k, agreements(tablesOf(rows, data, approximations, ""), k, resamples, seed, abc.fit), {}};
    const std::vector<FigureAgreement>& overall = tables.overall;
    v["overall"] = agreementsJson(overall, k);
    Json byLighting = Json::object();
    for (const std::string& l : lightings) {
      tables.byLighting[l] = agreements(tablesOf(rows, data, approximations, l), k, resamples, seed, abc.fit + "/" + l);
      byLighting[l] = agreementsJson(tables.byLighting[l], k);
    }
    v["byLighting"] = byLighting;
    variants.push_back(v);
    out.markdown += markdownOf(tables) + "\n";
    if (const std::string tex = texOf(tables); !tex.empty()) out.tex += tex + "\n";
    out.headline += "Within a material (people's closest among ABC as " + abc.fit + ", Ngan's Ward, Blinn-Phong, Lafortune, Bagher's SGD";
    const FigureAgreement* best = bestOf(overall);
    if (!best) {
      out.headline += "): no material has a figure and a perceived distance for all five.\n";
      continue;
    }
    out.headline += "; " + std::to_string(best->materials) + " materials): " + best->figure + " names people's closest for " +
                    intervalText(best->share, "%.2f") + " (chance " + formatted("%.2f", 1.0 / double(k)) + "); mean Kendall τ " +
                    intervalText(best->tau, "%.2f") + ", pooled Spearman ρ " + intervalText(best->rho, "%.2f") + ".\n";
  }
  j["variants"] = variants;
  return out;
}

}  // namespace glossy::study
