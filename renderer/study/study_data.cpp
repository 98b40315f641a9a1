#include "renderer/study/study_data.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/study/study_intervals.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <tuple>

namespace glossy::study {

namespace {

void checkFinite(const StudyRow& r, const Opt& v, const char* what) {
  if (v && !std::isfinite(*v))
    throw InputError("study row " + printableLine(r.material, 80) + " / " + printableLine(r.lighting, 40) + " / " +
                     printableLine(r.label, 40) + ": " + what + " is not a finite number");
}

}  // namespace

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

Interval addCorrelations(Json& out, std::size_t materials, const std::function<Pair(const std::vector<std::size_t>&)>& pairsOf,
                         int resamples, std::uint64_t seed, const std::string& key) {
  Interval spearmanInterval;
  // Not a structured binding: clang before 16 cannot capture one in the lambda (the fuzzers' build is clang).
  for (const auto& named : kCorrelations) {
    const char* const name = named.first;
    const Corr corr = named.second;
    const Interval iv = materialInterval(
        materials,
        [&](const std::vector<std::size_t>& drawn) {
          const Pair p = pairsOf(drawn);
          return corr(p.x, p.y);
        },
        resamples, seedFor(seed, key + "/" + name));
    out[name] = intervalJson(iv);
    if (std::string(name) == "spearman") spearmanInterval = iv;
  }
  return spearmanInterval;
}

}  // namespace glossy::study
