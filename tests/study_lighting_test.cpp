// The study's lighting outputs (renderer/study/study_lighting.h), through analyseStudy: every figure is
// recomputed here from the rows by its textbook formula, independently of renderer/study/study_statistics
// (ranks by counting, Friedman's χ² with df 2's closed-form survival, Wilcoxon's p by enumerating the signs,
// Kendall's W from rank sums), on a study whose verdicts are set by hand so that which materials change
// verdict is known.
#include "renderer/study/study_analysis.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>

namespace glossy::study {
namespace {

using test::TempDir;
using Json = nlohmann::json;

const std::vector<std::string> kLightings = {"a", "b", "c"};
const std::vector<std::string> kModels = {"X", "Y", "Z"};

// Each material's verdict under lightings a, b, c: one letter a closest model, two a tie, "-" none.
const std::vector<std::array<std::string, 3>> kVerdicts = {
    {"X", "Y", "X"},    // m00: changes (X against Y)
    {"X", "XY", "X"},   // m01: X against a tie of X and Y: left open by the noise, not a change
    {"X", "-", "-"},    // m02: one verdict, nothing to compare
    {"-", "-", "-"},    // m03: none
    {"XY", "YZ", "XY"},  // m04: the ties share Y
    {"X", "YZ", "-"},   // m05: changes (X against a tie of Y and Z)
    {"X", "X", "X"},  {"X", "X", "X"}, {"X", "X", "X"}, {"X", "X", "X"}, {"X", "X", "X"}, {"X", "X", "X"},
};

struct Lcg {
  std::uint64_t s = 987654321;
  double next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return double(s >> 11) / double(1ull << 53);
  }
};

std::string materialName(std::size_t i) { return (i < 10 ? "m0" : "m") + std::to_string(i); }

// r* of material i, lighting l, model k: X lowest on the whole, but often overtaken, so the rankings vary.
std::vector<StudyRow> lightingStudy(std::size_t materials = kVerdicts.size()) {
  std::vector<StudyRow> rows;
  Lcg rng;
  for (std::size_t i = 0; i < materials; ++i)
    for (std::size_t l = 0; l < kLightings.size(); ++l)
      for (std::size_t k = 0; k < kModels.size(); ++k) {
        StudyRow r;
        r.material = materialName(i);
        r.database = "MERL";
        r.lighting = kLightings[l];
        r.scene = "preview";
        r.label = kModels[k];
        r.fit = "model" + kModels[k] + ":E2";
        r.fitMetric = "E2";
        r.fitSource = "published";
        // Under lighting c, Y and Z trade places: the lightings' mean ranks disagree.
        const double place = l == 2 && k > 0 ? double(3 - k) : double(k);
        r.rrmse = 0.05 * (1.0 + 0.4 * place * rng.next() + 0.5 * rng.next());
        r.e1 = 0.1 + rng.next();
        r.e2 = 0.1 + rng.next();
        const std::string& v = kVerdicts[i % kVerdicts.size()][l];
        r.closest = v.size() == 1 && v == kModels[k];
        r.tied = v.size() == 2 && v.find(kModels[k]) != std::string::npos;
        r.sheet = "sheets/preview/" + r.lighting + "/" + r.material + ".exr";
        r.width = r.height = 16;
        r.spp = 4;
        r.seed = 1;
        rows.push_back(r);
      }
  return rows;
}

AnalysisOptions options() {
  AnalysisOptions o;
  o.resamples = 300;
  return o;
}

// r*[lighting][material][model] from the rows.
using Table = std::vector<std::vector<std::vector<double>>>;
Table tableOf(const std::vector<StudyRow>& rows, std::size_t materials) {
  Table t(kLightings.size(), std::vector<std::vector<double>>(materials, std::vector<double>(kModels.size())));
  for (const StudyRow& r : rows) {
    const auto l = std::size_t(std::find(kLightings.begin(), kLightings.end(), r.lighting) - kLightings.begin());
    const auto k = std::size_t(std::find(kModels.begin(), kModels.end(), r.label) - kModels.begin());
    t[l][std::size_t(std::stoi(r.material.substr(1)))][k] = *r.rrmse;
  }
  return t;
}

// Ranks by counting (1 = lowest), a tie given the mean of the ranks it spans.
std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<double> r;
  for (double x : v) {
    double below = 0, equal = 0;  // `equal` counts x itself
    for (double y : v) {
      if (y < x) below += 1;
      if (y == x) equal += 1;
    }
    r.push_back(below + (equal + 1.0) / 2.0);
  }
  return r;
}

// Kendall's W of raters (rows) over items, tie-corrected: 12 S / (m²(n³ − n) − m Σ T).
double kendallWByHand(const std::vector<std::vector<double>>& scores) {
  const double m = double(scores.size()), n = double(scores[0].size());
  std::vector<double> sum(scores[0].size(), 0.0);
  double ties = 0.0;
  for (const auto& row : scores) {
    const auto r = ranks(row);
    for (std::size_t j = 0; j < r.size(); ++j) sum[j] += r[j];
    std::map<double, int> count;
    for (double x : row) ++count[x];
    for (const auto& [x, t] : count) ties += double(t) * t * t - t;
  }
  double s = 0.0;
  for (double x : sum) s += (x - m * (n + 1) / 2) * (x - m * (n + 1) / 2);
  return 12.0 * s / (m * m * (n * n * n - n) - m * ties);
}

// Wilcoxon's two-sided exact p by enumerating every assignment of signs to the ranks (no ties, no zeros).
double wilcoxonExactByHand(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> d, a;
  for (std::size_t i = 0; i < x.size(); ++i) d.push_back(x[i] - y[i]);
  for (double v : d) a.push_back(std::fabs(v));
  const auto r = ranks(a);
  double wPlus = 0;
  for (std::size_t i = 0; i < d.size(); ++i) wPlus += d[i] > 0 ? r[i] : 0;
  const double total = double(d.size()) * double(d.size() + 1) / 2, w = std::min(wPlus, total - wPlus);
  const std::size_t n = d.size();
  double atMost = 0;
  for (std::uint64_t signs = 0; signs < (1ull << n); ++signs) {
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += (signs >> i & 1) ? double(i + 1) : 0.0;
    atMost += sum <= w + 1e-9 ? 1 : 0;
  }
  return std::min(1.0, 2.0 * atMost / double(1ull << n));
}

double medianOf(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

const Json& modelIn(const Json& lighting, const std::string& label) {
  for (const Json& m : lighting["models"])
    if (m["label"] == label) return m;
  throw std::runtime_error("no model " + label);
}

TEST(StudyLighting, EachLightingsRanksTestsAndMediansAreTheRowsOwn) {
  TempDir dir;
  const auto rows = lightingStudy();
  analyseStudy(rows, options(), dir.path());
  const Json r = Json::parse(test::readText(dir / "results.json"));
  const Json& lighting = r["lighting"];
  ASSERT_EQ(lighting["lightings"], Json(kLightings));
  const std::size_t n = kVerdicts.size();
  const Table t = tableOf(rows, n);
  for (std::size_t l = 0; l < kLightings.size(); ++l) {
    const Json& jl = lighting["perLighting"][l];
    SCOPED_TRACE(jl.dump(1));
    ASSERT_EQ(jl["lighting"], kLightings[l]);
    EXPECT_EQ(jl["materials"], int(n));
    EXPECT_EQ(jl["sheets"], int(n));
    // Mean ranks, and Friedman's χ² without ties: 12 / (N k (k + 1)) Σ R² − 3 N (k + 1), p = e^(−χ²/2) at df 2.
    std::vector<double> rankSum(kModels.size(), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const auto rk = ranks(t[l][i]);
      for (std::size_t k = 0; k < kModels.size(); ++k) rankSum[k] += rk[k];
    }
    double ss = 0;
    for (double x : rankSum) ss += x * x;
    const double k = double(kModels.size()), N = double(n);
    const double chi2 = 12.0 / (N * k * (k + 1)) * ss - 3.0 * N * (k + 1);
    EXPECT_NEAR(jl["friedman"]["chiSquare"].get<double>(), chi2, 1e-9);
    EXPECT_EQ(jl["friedman"]["df"], 2);
    EXPECT_NEAR(jl["friedman"]["p"].get<double>(), std::exp(-chi2 / 2), 1e-9);
    std::vector<std::size_t> order = {0, 1, 2};
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rankSum[a] < rankSum[b]; });
    for (std::size_t m = 0; m < kModels.size(); ++m) {
      const Json& jm = modelIn(jl, kModels[m]);
      EXPECT_NEAR(jm["meanRank"].get<double>(), rankSum[m] / N, 1e-12) << kModels[m];
      std::vector<double> v;
      for (std::size_t i = 0; i < n; ++i) v.push_back(t[l][i][m]);
      EXPECT_NEAR(jm["medianRrmse"]["estimate"].get<double>(), medianOf(v), 1e-15);
      ASSERT_FALSE(jm["medianRrmse"]["lo"].is_null()) << "12 materials carry an interval";
      EXPECT_LE(jm["medianRrmse"]["lo"].get<double>(), medianOf(v));
      EXPECT_GE(jm["medianRrmse"]["hi"].get<double>(), medianOf(v));
      int closest = 0, tied = 0;
      for (std::size_t i = 0; i < n; ++i) {
        const std::string& verdict = kVerdicts[i][l];
        closest += verdict == kModels[m] ? 1 : 0;
        tied += verdict.size() == 2 && verdict.find(kModels[m]) != std::string::npos ? 1 : 0;
      }
      EXPECT_EQ(jm["closest"], closest);
      EXPECT_EQ(jm["tied"], tied);
    }
    // The top pair: the two lowest mean ranks, tested on their r* over the materials.
    const Json& top = jl["topPair"];
    EXPECT_EQ(top["a"], kModels[order[0]]);
    EXPECT_EQ(top["b"], kModels[order[1]]);
    std::vector<double> x, y;
    for (std::size_t i = 0; i < n; ++i) {
      x.push_back(t[l][i][order[0]]);
      y.push_back(t[l][i][order[1]]);
    }
    EXPECT_EQ(top["method"], "exact");
    EXPECT_NEAR(top["p"].get<double>(), wilcoxonExactByHand(x, y), 1e-12);
  }
}

TEST(StudyLighting, KendallsWAcrossLightingsIsTheRowsOwnWithAnInterval) {
  TempDir dir;
  const auto rows = lightingStudy();
  analyseStudy(rows, options(), dir.path());
  const Json w = Json::parse(test::readText(dir / "results.json"))["lighting"]["kendallW"];
  SCOPED_TRACE(w.dump(1));
  const std::size_t n = kVerdicts.size();
  const Table t = tableOf(rows, n);
  // Per material: raters = the three lightings, items = the three models.
  std::vector<double> perMaterial;
  for (std::size_t i = 0; i < n; ++i) perMaterial.push_back(kendallWByHand({t[0][i], t[1][i], t[2][i]}));
  double mean = 0;
  for (double x : perMaterial) mean += x / double(n);
  EXPECT_NEAR(w["meanOverMaterials"]["estimate"].get<double>(), mean, 1e-12);
  EXPECT_NEAR(w["meanOverMaterials"]["median"].get<double>(), medianOf(perMaterial), 1e-12);
  EXPECT_EQ(w["meanOverMaterials"]["materials"], int(n));
  ASSERT_FALSE(w["meanOverMaterials"]["lo"].is_null());
  EXPECT_LE(w["meanOverMaterials"]["lo"].get<double>(), mean);
  EXPECT_GE(w["meanOverMaterials"]["hi"].get<double>(), mean);
  // Of the lightings' mean ranks: raters = lightings, their scores the models' mean ranks.
  std::vector<std::vector<double>> meanRanks(kLightings.size(), std::vector<double>(kModels.size(), 0.0));
  for (std::size_t l = 0; l < kLightings.size(); ++l)
    for (std::size_t i = 0; i < n; ++i) {
      const auto rk = ranks(t[l][i]);
      for (std::size_t k = 0; k < kModels.size(); ++k) meanRanks[l][k] += rk[k] / double(n);
    }
  ASSERT_LT(kendallWByHand(meanRanks), 0.9) << "the study is built so that the lightings' mean ranks disagree";
  EXPECT_NEAR(w["ofMeanRanks"]["estimate"].get<double>(), kendallWByHand(meanRanks), 1e-12);
  EXPECT_EQ(w["ofMeanRanks"]["materials"], int(n));
}

TEST(StudyLighting, TheMaterialsWhoseVerdictChangesAreCountedAndListed) {
  TempDir dir;
  const auto rows = lightingStudy();
  const auto res = analyseStudy(rows, options(), dir.path());
  const Json r = Json::parse(test::readText(dir / "results.json"))["lighting"];
  SCOPED_TRACE(r.dump(1));
  // m02 and m03 have fewer than two verdicts to compare; of the other ten, m00 and m05 change.
  EXPECT_EQ(r["verdictChanges"]["materials"], 10);
  EXPECT_EQ(r["verdictChanges"]["changed"], 2);
  ASSERT_EQ(r["verdictChanges"]["list"].size(), 2u);
  EXPECT_EQ(r["verdictChanges"]["list"][0]["material"], "m00");
  EXPECT_EQ(r["verdictChanges"]["list"][1]["material"], "m05");
  EXPECT_EQ(r["verdictChanges"]["list"][1]["sheets"][1]["models"], Json({"Y", "Z"}));
  // The lowest r* changes wherever the three lightings' lowest models are not all one.
  const Table t = tableOf(rows, kVerdicts.size());
  std::vector<std::string> lowestChanged;
  for (std::size_t i = 0; i < kVerdicts.size(); ++i) {
    std::set<std::size_t> lowest;
    for (std::size_t l = 0; l < kLightings.size(); ++l)
      lowest.insert(std::size_t(std::min_element(t[l][i].begin(), t[l][i].end()) - t[l][i].begin()));
    if (lowest.size() > 1) lowestChanged.push_back(materialName(i));
  }
  ASSERT_FALSE(lowestChanged.empty()) << "the study is built so that some lowest models change";
  EXPECT_EQ(r["lowestRrmseChanges"]["materials"], int(kVerdicts.size()));
  EXPECT_EQ(r["lowestRrmseChanges"]["changed"], int(lowestChanged.size()));
  for (std::size_t j = 0; j < lowestChanged.size(); ++j) EXPECT_EQ(r["lowestRrmseChanges"]["list"][j]["material"], lowestChanged[j]);
  // The summary (printed and summary.md) says it, with the list.
  EXPECT_NE(res.summary.find("the closest model changes with the lighting for 2 of 10 materials"), std::string::npos) << res.summary;
  const std::string md = test::readText(dir / "summary.md");
  EXPECT_NE(md.find("## Lighting"), std::string::npos) << md;
  EXPECT_NE(md.find("for 2 of 10 materials with a verdict under two lightings or more: m00 (a: X, b: Y, c: X); m05 (a: X, b: tie: Y, Z, c: none)"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("| model | mean rank | median r* [95 %] | closest | tied |"), std::string::npos) << md;
}

// lighting.tex: one table float with caption and label, every lighting's rows and tests; it compiles with
// pdflatex alone (no package) and fits an article's page, at 12 materials and at 3, where its reasons
// carry a "≥".
TEST(StudyLighting, TheLatexTableHasCaptionLabelAndCompiles) {
  const bool pdflatex = std::system("command -v pdflatex > /dev/null 2>&1") == 0;
  for (const std::size_t materials : {kVerdicts.size(), std::size_t(3)}) {
    TempDir dir;
    analyseStudy(lightingStudy(materials), options(), dir.path());
    const std::string tex = test::readText(dir / "lighting.tex");
    SCOPED_TRACE(tex);
    EXPECT_NE(tex.find("\\caption{"), std::string::npos);
    EXPECT_NE(tex.find("\\label{tab:glossy-study-lighting}"), std::string::npos);
    EXPECT_EQ(tex.find("booktabs"), std::string::npos);
    for (const std::string& l : kLightings) EXPECT_NE(tex.find("\n" + l + " (" + std::to_string(materials) + ") & "), std::string::npos) << l;
    if (materials < 6) {
      EXPECT_NE(tex.find("\\emph{a}: Friedman: n/a: 3 materials; tests need $\\geq$ 6"), std::string::npos);
    } else {
      EXPECT_NE(tex.find("\\emph{a}: Friedman $\\chi^2 = "), std::string::npos);
    }
    if (!pdflatex) continue;
    test::writeText(dir / "paper.tex", "\\documentclass{article}\n\\begin{document}\n\\input{lighting.tex}\n\\end{document}\n");
    const std::string command = "cd " + test::shellQuote(dir.path().string()) +
                                " && pdflatex -interaction=nonstopmode -halt-on-error paper.tex > pdflatex.log 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << test::readText(dir / "pdflatex.log");
    EXPECT_TRUE(std::filesystem::exists(dir / "paper.pdf"));
    EXPECT_EQ(test::readText(dir / "paper.log").find("Overfull \\hbox"), std::string::npos) << "the table fits the page";
  }
  if (!pdflatex) GTEST_SKIP() << "pdflatex is not installed: the table's text is checked, not its compilation";
}

}  // namespace
}  // namespace glossy::study
