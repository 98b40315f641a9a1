// How the models rank (docs/study.md, "The statistics"): the Friedman test over the materials with every
// model, every pair by Holm-corrected Wilcoxon signed-rank tests and the groups of models they do not part,
// each model's wins, ties, mean rank and mean and median r* with their intervals, and the share of materials
// on which each model is closer than each other (over all, per database, per material class).
#pragma once

#include "renderer/study/study_analysis.h"
#include "renderer/study/study_data.h"

#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace glossy::study {

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

RankTests rankTests(const Study& s);
// results.json's "models": a row per model.
Json perModel(const Study& s, const RankTests& t, const AnalysisOptions& o);
// results.json's "friedman" and "wilcoxon".
void addRankTests(const Study& s, const RankTests& t, Json& results);
// results.json's "closerThan".
Json closerThan(const Study& s, const AnalysisOptions& options);

}  // namespace glossy::study
