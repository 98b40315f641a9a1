#include "renderer/study/study_claim.h"

#include "renderer/study/study_intervals.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace glossy::study {

namespace {

using Column = std::vector<std::vector<Opt>> Study::*;

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

// A BRDF-space error's correlations with an image error pooled over every (material, model) pair; `key`
// names the two ("E1/rrmse"), `rho` is set to the Spearman ρ.
Json pooledCorrelations(const Study& s, const AnalysisOptions& o, Column brdf, Column image, const std::string& key, Interval& rho) {
  std::vector<std::size_t> all(s.materials.size());
  std::iota(all.begin(), all.end(), 0);
  Json jp;
  jp["pairs"] = int(pooled(s, brdf, image, all).x.size());
  rho = addCorrelations(jp, all.size(), [&](const std::vector<std::size_t>& idx) { return pooled(s, brdf, image, idx); }, o.resamples,
                        o.seed, "pooled/" + key);
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

}  // namespace

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

}  // namespace glossy::study
