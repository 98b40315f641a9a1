#include "renderer/study/study_people.h"

#include "materials/core/text.h"
#include "renderer/study/study_intervals.h"
#include "renderer/study/study_statistics.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>

namespace glossy::study {

namespace {

using Json = nlohmann::ordered_json;
using Opt = std::optional<double>;

constexpr const char* kFigures[] = {"rrmse", "flip", "e1", "e2"};
constexpr std::size_t kFigureCount = std::size(kFigures);

Opt figureOf(const StudyRow& r, std::size_t f) {
  const Opt values[] = {r.rrmse, r.flip, r.e1, r.e2};
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

}  // namespace

PeopleAnalysis closestToPeople(const std::vector<const StudyRow*>& rows, const PerceptualData& data, int resamples,
                               std::uint64_t seed) {
  PeopleAnalysis out;
  Json& j = out.json;
  j["question"] = "within a material, which approximation looks closest: glossy's figures against people's";
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
    const std::vector<FigureAgreement> overall = agreements(tablesOf(rows, data, approximations, ""), k, resamples, seed, abc.fit);
    v["overall"] = agreementsJson(overall, k);
    Json byLighting = Json::object();
    for (const std::string& l : lightings)
      byLighting[l] = agreementsJson(agreements(tablesOf(rows, data, approximations, l), k, resamples, seed, abc.fit + "/" + l), k);
    v["byLighting"] = byLighting;
    variants.push_back(v);
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
