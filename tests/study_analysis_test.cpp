// The study's analysis (renderer/study/study_analysis.h) on synthetic studies built so that the answer is
// known: one model closest everywhere, E2 ordered with the image error and E1 not; plus the perceptual
// tables it reads (renderer/study/perceptual.h). The statistics themselves are checked against scipy in
// study_statistics_test.cpp.
#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/study/perceptual.h"
#include "renderer/study/study_analysis.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <regex>

namespace glossy::study {
namespace {

using test::TempDir;
using Json = nlohmann::json;

// MERL materials as the perceptual dataset and glossy's library spell them.
const std::vector<std::string> kMaterials = {"alum-bronze", "alumina-oxide", "aluminium", "aventurnine", "beige-fabric",
                                             "black-fabric", "black-obsidian", "black-oxidized-steel", "black-phenolic",
                                             "black-soft-plastic", "blue-acrylic", "blue-fabric"};

struct Model {
  std::string label, fit, metric;
  double factor;  // its error relative to the material's base error
};
const std::vector<Model> kModels = {{"Microfacet E2", "microfacet:E2", "E2", 0.5},
                                    {"Smooth E2", "smooth:E2", "E2", 1.0},
                                    {"CT E1", "cook-torrance:E1", "E1", 1.4},
                                    {"AS E2", "ashikhmin-shirley:E2", "E2", 1.9}};

// A fixed pseudo-random sequence (a 64-bit LCG), so the study is the same on every run.
struct Lcg {
  std::uint64_t s = 12345;
  double next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return double(s >> 11) / double(1ull << 53);
  }
};

// 12 materials × 2 lightings × 4 models. "Microfacet E2" is built to be best: half the error of any other
// model, named closest on every sheet but two, where it ties with Smooth E2. E2 rises with the image error
// within each material; E1 is noise.
std::vector<StudyRow> syntheticStudy() {
  std::vector<StudyRow> rows;
  Lcg rng;
  for (std::size_t i = 0; i < kMaterials.size(); ++i)
    for (const std::string lighting : {"sky", "studio"}) {
      const double base = 0.04 * (1.0 + 0.25 * double(i)) * (lighting == "sky" ? 1.0 : 1.3);
      const bool tie = (i == 3 && lighting == "sky") || (i == 7 && lighting == "studio");
      for (const Model& m : kModels) {
        StudyRow r;
        r.material = kMaterials[i];
        r.database = "MERL";
        r.materialClass = i % 2 ? "Dielectric" : "Metal";
        r.lighting = lighting;
        r.scene = "sphere";
        r.layer = m.fit.substr(0, m.fit.find(':')) + "_" + m.metric;
        r.label = m.label;
        r.fit = m.fit;
        r.fitMetric = m.metric;
        r.fitSource = "published";
        const double noise = 0.1 * rng.next();
        r.rrmse = base * m.factor * (1.0 + noise);
        r.rrmseLo = *r.rrmse * 0.97;
        r.rrmseHi = *r.rrmse * 1.03;
        r.flip = 0.1 + *r.rrmse;
        r.flipLo = *r.flip - 0.01;
        r.flipHi = *r.flip + 0.01;
        r.e2 = 0.01 * m.factor * (1.0 + 0.1 * double(i));
        r.e1 = 0.02 + 0.05 * rng.next();
        r.luminanceRatio = 1.0;
        r.closest = m.label == "Microfacet E2" && !tie;
        r.tied = tie && (m.label == "Microfacet E2" || m.label == "Smooth E2");
        r.sheet = "sheets/" + r.material + "_" + lighting + ".exr";
        r.width = r.height = 64;
        r.spp = 16;
        r.seed = 1;
        rows.push_back(r);
      }
    }
  return rows;
}

AnalysisOptions fastOptions() {
  AnalysisOptions o;
  o.resamples = 400;  // enough for the assertions; the default (2000) is exercised by determinism
  return o;
}

Json results(const TempDir& dir) { return Json::parse(test::readText(dir / "results.json")); }

const Json& modelEntry(const Json& r, const std::string& label) {
  for (const Json& m : r["models"])
    if (m["label"] == label) return m;
  throw std::runtime_error("no model " + label);
}

void expectNoNanOrInf(const TempDir& dir, const AnalysisResult& res) {
  static const std::regex kBad(R"((^|[^A-Za-z])(nan|NaN|inf|Inf|INF|NAN)([^A-Za-z]|$))");
  for (const auto& f : res.files) {
    if (f.extension() == ".png") continue;
    const std::string text = test::readText(dir / f);
    EXPECT_FALSE(std::regex_search(text, kBad)) << f << " holds NaN or Inf";
  }
}

TEST(StudyAnalysis, TheModelBuiltToBeBestIsNamedBestEverywhere) {
  TempDir dir;
  const auto rows = syntheticStudy();
  const auto res = analyseStudy(rows, fastOptions(), dir.path());
  const Json r = results(dir);
  SCOPED_TRACE(r.dump(1));
  EXPECT_EQ(r["counts"]["materials"], 12);
  EXPECT_EQ(r["counts"]["sheets"], 24);
  const Json& best = modelEntry(r, "Microfacet E2");
  EXPECT_EQ(best["closest"], 22);
  EXPECT_EQ(best["tied"], 2);
  EXPECT_EQ(best["meanRank"], 1.0);
  EXPECT_EQ(modelEntry(r, "Smooth E2")["closest"], 0);
  for (const Json& m : r["models"])
    if (m["label"] != "Microfacet E2") {
      EXPECT_LT(best["meanRrmse"]["hi"].get<double>(), m["meanRrmse"]["lo"].get<double>()) << m["label"];
    }
  EXPECT_LT(r["friedman"]["p"].get<double>(), 1e-4);
  EXPECT_LT(r["friedman"]["pF"].get<double>(), 1e-4);
  // Every pair is separated (12 materials, the order is the same on each): exact tests, all significant.
  for (const Json& p : r["wilcoxon"]["pairs"]) {
    EXPECT_EQ(p["method"], "exact");
    EXPECT_TRUE(p["significant"].get<bool>()) << p.dump();
  }
  EXPECT_TRUE(r["wilcoxon"]["cliques"].empty());
  for (const Json& c : r["closerThan"]["overall"])
    if (c["x"] == "Microfacet E2") {
      EXPECT_EQ(c["share"]["estimate"], 1.0) << c.dump();
    }
  EXPECT_TRUE(r["closerThan"]["byClass"].contains("Metal"));
  EXPECT_TRUE(r["closerThan"]["byDatabase"].contains("MERL"));
  // Per material: the same verdict under both lightings, no flip, rankings in full agreement.
  for (const Json& m : r["materials"]) {
    EXPECT_EQ(m["acrossLightings"]["model"], "Microfacet E2");
    EXPECT_EQ(m["acrossLightings"]["flips"], 0);
    EXPECT_EQ(m["kendallW"]["value"], 1.0);
  }
  EXPECT_NE(res.summary.find("Microfacet E2: closest on 22 of 24 sheets"), std::string::npos) << res.summary;
  EXPECT_NE(test::readText(dir / "summary.md").find("Microfacet E2: closest on 22 of 24"), std::string::npos);
  expectNoNanOrInf(dir, res);
}

TEST(StudyAnalysis, E2OrderedWithTheImageErrorIsSaidToPredictItBetterThanE1) {
  TempDir dir;
  const auto res = analyseStudy(syntheticStudy(), fastOptions(), dir.path());
  const Json r = results(dir);
  const Json* e1 = nullptr;
  const Json* e2 = nullptr;
  for (const Json& c : r["brdfVsImage"]) {
    if (c["image"] != "rrmse") continue;
    (c["brdf"] == "E1" ? e1 : e2) = &c;
  }
  ASSERT_TRUE(e1 && e2);
  EXPECT_EQ((*e2)["withinMaterial"]["spearman"]["estimate"], 1.0);
  EXPECT_EQ((*e2)["bestIsImageBest"]["share"]["estimate"], 1.0);
  EXPECT_GT((*e2)["pooled"]["spearman"]["lo"].get<double>(), (*e1)["pooled"]["spearman"]["hi"].get<double>());
  EXPECT_GT(r["e2MinusE1"][0]["pooledSpearman"]["lo"].get<double>(), 0.0);
  EXPECT_NE(res.summary.find("E2 predicts image error better than E1"), std::string::npos) << res.summary;
}

// Spearman's ρ of two columns without ties, by the textbook formula 1 − 6 Σ d² / (n (n² − 1)), ranks by counting.
double spearmanWithoutTies(const std::vector<double>& x, const std::vector<double>& y) {
  const auto rank = [](const std::vector<double>& v, std::size_t i) { return double(std::count_if(v.begin(), v.end(), [&](double u) { return u < v[i]; })); };
  double d2 = 0;
  for (std::size_t i = 0; i < x.size(); ++i) d2 += (rank(x, i) - rank(y, i)) * (rank(x, i) - rank(y, i));
  const double n = double(x.size());
  return 1.0 - 6.0 * d2 / (n * (n * n - 1.0));
}

// Löw et al.'s question is asked within a material, across its fits: each material's ρ of E2 with r*
// minus its ρ of E1 with r*, the mean over materials with a paired interval — beside the pooled difference,
// the summary saying which question each answers.
TEST(StudyAnalysis, TheWithinMaterialDifferenceOfE2AndE1IsTheMeanOfEachMaterialsOwn) {
  TempDir dir;
  const auto rows = syntheticStudy();
  const auto res = analyseStudy(rows, fastOptions(), dir.path());
  const Json r = results(dir);
  // Each material's figures are the means over its two lightings.
  double sum = 0;
  for (const std::string& m : kMaterials) {
    std::vector<double> rr, e1, e2;
    for (const Model& model : kModels) {
      double a = 0, b = 0, c = 0;
      for (const StudyRow& row : rows)
        if (row.material == m && row.label == model.label) {
          a += *row.rrmse / 2;
          b += *row.e1 / 2;
          c += *row.e2 / 2;
        }
      rr.push_back(a);
      e1.push_back(b);
      e2.push_back(c);
    }
    sum += spearmanWithoutTies(e2, rr) - spearmanWithoutTies(e1, rr);
  }
  const double expected = sum / double(kMaterials.size());
  const Json& within = r["e2MinusE1"][0]["withinMaterialSpearman"];
  SCOPED_TRACE(within.dump());
  ASSERT_EQ(r["e2MinusE1"][0]["image"], "rrmse");
  EXPECT_NEAR(within["estimate"].get<double>(), expected, 1e-12);
  EXPECT_EQ(within["materials"], 12);
  ASSERT_FALSE(within["lo"].is_null());
  EXPECT_LT(within["lo"].get<double>(), expected);
  EXPECT_GT(within["hi"].get<double>(), expected);
  EXPECT_GT(within["lo"].get<double>(), 0.0) << "E2 follows r* on every material, E1 is noise";
  EXPECT_FALSE(r["e2MinusE1"][0]["pooledSpearman"]["estimate"].is_null());
  EXPECT_NE(res.summary.find("Across materials (pooled over every material and model)"), std::string::npos) << res.summary;
  EXPECT_NE(res.summary.find("Across a material's fits (within each material, then the mean; Löw et al.'s question)"), std::string::npos);
  EXPECT_NE(res.summary.find(formatted("E2 − E1 %.3f [", expected)), std::string::npos) << res.summary;
}

// Every interval of results.json either has two different ends or is absent with its reason; none reads
// [x, x].
void expectNoDegenerateInterval(const Json& j, const std::string& where = "") {
  if (j.is_object()) {
    if (j.contains("lo") && j.contains("hi") && j.contains("estimate")) {
      if (!j["lo"].is_null()) {
        EXPECT_NE(j["lo"].get<double>(), j["hi"].get<double>()) << where << ": " << j.dump();
      } else if (!j["estimate"].is_null()) {
        EXPECT_TRUE(j.contains("reason") && !j["reason"].get<std::string>().empty()) << where << ": " << j.dump();
      }
    }
    for (const auto& [k, v] : j.items()) expectNoDegenerateInterval(v, where + "/" + k);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) expectNoDegenerateInterval(j[i], where + "/" + std::to_string(i));
  }
}

std::vector<StudyRow> firstMaterials(std::size_t n) {
  std::vector<StudyRow> rows;
  for (const StudyRow& r : syntheticStudy())
    if (std::find(kMaterials.begin(), kMaterials.begin() + std::ptrdiff_t(n), r.material) != kMaterials.begin() + std::ptrdiff_t(n))
      rows.push_back(r);
  return rows;
}

// Below 10 materials no interval, below 6 no test: each absent with the reason, never a degenerate interval
// or a finding; and where every material agrees (a share of 1), no [1, 1] either.
TEST(StudyAnalysis, SmallSamplesAreStatedAsSuchNeverAsFindings) {
  {
    TempDir dir;
    const auto res = analyseStudy(firstMaterials(1), fastOptions(), dir.path());
    const Json r = results(dir);
    expectNoDegenerateInterval(r);
    const std::string md = test::readText(dir / "summary.md");
    EXPECT_EQ(md.find("predicts image error better"), std::string::npos) << md;
    EXPECT_NE(md.find("not decided"), std::string::npos) << md;
    EXPECT_NE(md.find("n/a: 1 material; intervals need \xE2\x89\xA5 10"), std::string::npos) << md;
    EXPECT_NE(md.find("no test (n/a: 1 material; tests need \xE2\x89\xA5 6)"), std::string::npos) << md;
    EXPECT_FALSE(std::regex_search(md, std::regex(R"(\[([-0-9.e]+), \1\])"))) << md;
    EXPECT_EQ(r["e2MinusE1"][0]["pooledSpearman"]["reason"], "n/a: 1 material; intervals need \xE2\x89\xA5 10");
    EXPECT_TRUE(r["friedman"]["p"].is_null());
    EXPECT_EQ(r["friedman"]["reason"], "n/a: 1 material; tests need \xE2\x89\xA5 6");
    expectNoNanOrInf(dir, res);
  }
  {
    // Three materials: the mean ranks stand, the Friedman test does not.
    TempDir dir;
    analyseStudy(firstMaterials(3), fastOptions(), dir.path());
    const Json r = results(dir);
    expectNoDegenerateInterval(r);
    EXPECT_EQ(r["friedman"]["reason"], "n/a: 3 materials; tests need \xE2\x89\xA5 6");
    EXPECT_EQ(modelEntry(r, "Microfacet E2")["meanRank"], 1.0);
    EXPECT_TRUE(modelEntry(r, "Microfacet E2")["meanRrmse"]["lo"].is_null());
    EXPECT_EQ(modelEntry(r, "Microfacet E2")["meanRrmse"]["reason"], "n/a: 3 materials; intervals need \xE2\x89\xA5 10");
  }
  for (const std::size_t n : {std::size_t(8), kMaterials.size()}) {
    // 8 materials: too few for an interval, enough for a test; 12: an interval would be [1, 1].
    TempDir dir;
    analyseStudy(firstMaterials(n), fastOptions(), dir.path());
    const Json r = results(dir);
    expectNoDegenerateInterval(r);
    EXPECT_FALSE(r["friedman"]["p"].is_null());
    for (const Json& c : r["closerThan"]["overall"])
      if (c["x"] == "Microfacet E2") {
        EXPECT_EQ(c["share"]["estimate"], 1.0);
        EXPECT_TRUE(c["share"]["lo"].is_null()) << c.dump();
        EXPECT_EQ(c["share"]["reason"], n < 10 ? "n/a: 8 materials; intervals need \xE2\x89\xA5 10"
                                               : "no interval: every resample gives 1 (the 12 materials agree; the bootstrap cannot bound it)");
      }
    const std::string md = test::readText(dir / "summary.md");
    EXPECT_FALSE(std::regex_search(md, std::regex(R"(\[([-0-9.e]+), \1\])"))) << md;
  }
}

// Against people with 3 materials: the highest ρ is described, not called the figure that agrees best.
TEST(StudyAnalysis, AgainstPeopleASmallSampleNamesNoFigureThatAgreesBest) {
  GLOSSY_REQUIRE_SHARED("perceptual");
  TempDir dir;
  AnalysisOptions o = fastOptions();
  o.perceptualDir = test::sharedDir() / "perceptual";
  const auto res = analyseStudy(firstMaterials(3), o, dir.path());
  expectNoDegenerateInterval(results(dir));
  EXPECT_EQ(res.summary.find("agrees best"), std::string::npos) << res.summary;
  EXPECT_NE(res.summary.find("the highest Spearman ρ with the perceived distance is"), std::string::npos) << res.summary;
}

TEST(StudyAnalysis, PeopleAreComparedWithTheSharedFitOnlyWhereAModelCoversOthers) {
  GLOSSY_REQUIRE_SHARED("perceptual");
  // Microfacet E2 on the first three materials is glossy's own fit: those rows are not Löw's published
  // fit the dataset judged, so they stay out of the comparison with people (and the model lists both fits).
  auto rows = syntheticStudy();
  for (auto& r : rows)
    if (r.label == "Microfacet E2" && r.material < "av") {
      r.fit = "microfacet:E2:glossy";
      r.fitSource = "glossy";
    }
  TempDir dir;
  AnalysisOptions o = fastOptions();
  o.perceptualDir = test::sharedDir() / "perceptual";
  analyseStudy(rows, o, dir.path());
  const Json r = results(dir);
  for (const Json& f : r["againstPeople"]["fits"]) {
    if (f["fit"] == "microfacet:E2") {
      EXPECT_EQ(f["materials"], 9);
    } else {
      EXPECT_EQ(f["materials"], 12);
    }
  }
  EXPECT_EQ(modelEntry(r, "Microfacet E2")["fitSources"], Json({"glossy", "published"}));
}

TEST(StudyAnalysis, RowOrderDoesNotChangeAByte) {
  TempDir a, b;
  auto rows = syntheticStudy();
  AnalysisOptions o;  // the default 2000 resamples
  const auto ra = analyseStudy(rows, o, a.path());
  std::reverse(rows.begin(), rows.end());
  std::rotate(rows.begin(), rows.begin() + 17, rows.end());
  const auto rb = analyseStudy(rows, o, b.path());
  ASSERT_EQ(ra.files, rb.files);
  for (const auto& f : ra.files) EXPECT_EQ(test::readText(a / f.string()), test::readText(b / f.string())) << f;
  // And another seed moves the intervals (the seed is used).
  TempDir c;
  o.seed = 2;
  analyseStudy(rows, o, c.path());
  EXPECT_NE(test::readText(a / "results.json"), test::readText(c / "results.json"));
}

TEST(StudyAnalysis, WritesEveryOutput) {
  TempDir dir;
  const auto res = analyseStudy(syntheticStudy(), fastOptions(), dir.path());
  for (const char* f : {"rows.csv", "rows.json", "results.json", "models.tex", "lighting.tex", "summary.md", "error_curves.svg", "heat_map.svg",
                        "critical_difference.svg", "brdf_vs_image.svg"}) {
    EXPECT_TRUE(std::find(res.files.begin(), res.files.end(), std::filesystem::path(f)) != res.files.end()) << f;
    EXPECT_TRUE(std::filesystem::exists(dir / f)) << f;
  }
  const auto csv = test::readCsv(dir / "rows.csv");
  ASSERT_EQ(csv.size(), 96u);
  EXPECT_EQ(csv[0].at("fit_source"), "published");
  EXPECT_EQ(csv[0].at("spp"), "16");
  const std::string tex = test::readText(dir / "models.tex");
  EXPECT_NE(tex.find("\\toprule"), std::string::npos);
  EXPECT_NE(tex.find("Microfacet E2 & a & 22 & 2 & 1.00"), std::string::npos) << tex;
  EXPECT_NE(test::readText(dir / "critical_difference.svg").find("Microfacet E2 (1.00)"), std::string::npos);
}

TEST(StudyAnalysis, RowsWithoutAnImageErrorAreSkippedAndCounted) {
  TempDir dir;
  auto rows = syntheticStudy();
  rows[5].rrmse.reset();
  analyseStudy(rows, fastOptions(), dir.path());
  const Json r = results(dir);
  EXPECT_EQ(r["counts"]["rowsSkippedWithoutRrmse"], 1);
  EXPECT_EQ(r["counts"]["rowsUsed"], 95);
  EXPECT_EQ(test::readCsv(dir / "rows.csv").size(), 96u);  // still listed, with the figure empty
}

// The sheets' render noise, summarised from the rows' r* intervals: median and 90th percentile of the
// half-widths (numpy's default quantile) and the rows whose noise is as large as r*, in results.json, the
// summary and the methods paragraph. Rows without an interval do not count.
TEST(StudyAnalysis, RenderNoiseIsSummarisedFromTheRowsIntervals) {
  TempDir dir;
  auto rows = syntheticStudy();  // 96 rows
  std::vector<double> half;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    StudyRow& r = rows[i];
    if (i % 8 == 7) {  // 12 rows without an interval
      r.rrmseLo.reset();
      r.rrmseHi.reset();
      continue;
    }
    const double h = 0.001 * double(i + 1);
    r.rrmseLo = std::max(0.0, *r.rrmse - h);
    r.rrmseHi = *r.rrmse + h;
    half.push_back(0.5 * (*r.rrmseHi - *r.rrmseLo));
  }
  int asLarge = 0;
  for (const StudyRow& r : rows)
    if (r.rrmseLo) asLarge += 0.5 * (*r.rrmseHi - *r.rrmseLo) >= *r.rrmse ? 1 : 0;
  std::sort(half.begin(), half.end());
  const auto quantile = [&](double q) {  // type 7: linear between order statistics
    const double at = q * double(half.size() - 1);
    const std::size_t k = std::size_t(at);
    return half[k] + (at - double(k)) * (half[std::min(k + 1, half.size() - 1)] - half[k]);
  };
  ASSERT_EQ(half.size(), 84u);
  ASSERT_GT(asLarge, 0);
  ASSERT_LT(asLarge, 84);
  const auto res = analyseStudy(rows, fastOptions(), dir.path());
  const Json n = results(dir)["renderNoise"];
  EXPECT_EQ(n["rows"], 84);
  EXPECT_DOUBLE_EQ(n["medianHalfWidth"].get<double>(), quantile(0.5));
  EXPECT_DOUBLE_EQ(n["p90HalfWidth"].get<double>(), quantile(0.9));
  EXPECT_EQ(n["rowsHalfWidthAtLeastRrmse"], asLarge);
  const std::string said = formatted("median half-width of %.2g (90 %% at most %.2g); on %d of 84 rows", quantile(0.5), quantile(0.9), asLarge);
  EXPECT_NE(res.summary.find(said), std::string::npos) << said << "\n" << res.summary;
  const std::string methods = test::readText(dir / "methods.tex");
  EXPECT_NE(methods.find(formatted("median half-width of %.2g", quantile(0.5))), std::string::npos) << methods;
  EXPECT_NE(methods.find("which the intervals do not include"), std::string::npos) << methods;
}

TEST(StudyAnalysis, VerdictCountsSayHowManySheetsDecidedAndClampedEstimatesAreMarked) {
  TempDir dir;
  auto rows = syntheticStudy();  // 24 sheets: 22 name Microfacet E2 closest, 2 a tie
  for (auto& r : rows)
    if (r.material == kMaterials[5] && r.lighting == "sky") r.closest = false;  // a sheet without a verdict
  int clamped = 0;
  for (auto& r : rows)
    if (r.label == "Smooth E2" && clamped < 2) {
      r.rrmse = r.rrmseLo = 0.0;
      r.rrmseClamped = true;
      ++clamped;
    }
  const auto res = analyseStudy(rows, fastOptions(), dir.path());
  const Json r = results(dir);
  EXPECT_EQ(r["counts"]["sheetsDecided"], 21);
  EXPECT_EQ(r["counts"]["sheetsTied"], 2);
  EXPECT_EQ(r["counts"]["sheetsWithoutVerdict"], 1);
  EXPECT_EQ(r["counts"]["rowsRrmseClamped"], 2);
  EXPECT_EQ(modelEntry(r, "Smooth E2")["rrmseClamped"], 2);
  EXPECT_EQ(modelEntry(r, "Microfacet E2")["rrmseClamped"], 0);
  EXPECT_NE(res.summary.find("Verdicts: 21 of 24 sheets name one closest model, 2 a tie, 1 none"), std::string::npos) << res.summary;
  EXPECT_NE(res.summary.find("; 2 r* clamped to 0"), std::string::npos) << res.summary;
  EXPECT_NE(res.summary.find("Smooth E2: closest on 0 of 24 sheets, tied on 2; mean rank"), std::string::npos) << res.summary;
  EXPECT_NE(res.summary.find("r* clamped to 0 on 2\n"), std::string::npos) << res.summary;
  // The rows mark them: 1 in rows.csv, true in rows.json, for those two rows only.
  const auto csv = test::readCsv(dir / "rows.csv");
  int marked = 0;
  for (const auto& row : csv) {
    marked += row.at("rrmse_clamped") == "1" ? 1 : 0;
    if (row.at("rrmse_clamped") == "1") {
      EXPECT_EQ(row.at("rrmse"), "0");
    }
  }
  EXPECT_EQ(marked, 2);
  int inJson = 0;
  for (const Json& row : Json::parse(test::readText(dir / "rows.json"))) inJson += row["rrmseClamped"].get<bool>() ? 1 : 0;
  EXPECT_EQ(inJson, 2);
}

TEST(StudyAnalysis, UndefinedStatisticsAreNullWithAReasonNeverNaN) {
  TempDir dir;
  auto rows = syntheticStudy();
  for (auto& r : rows) r.flip = 0.25;  // a constant column: no rank correlation with it
  rows.resize(3 * 8);                  // three materials: too few pairs for a Wilcoxon test
  const auto res = analyseStudy(rows, fastOptions(), dir.path());
  const Json r = results(dir);
  for (const Json& c : r["brdfVsImage"])
    if (c["image"] == "flip") {
      EXPECT_TRUE(c["pooled"]["spearman"]["estimate"].is_null());
      EXPECT_FALSE(c["pooled"]["spearman"]["reason"].get<std::string>().empty());
      EXPECT_TRUE(c["withinMaterial"]["kendallTauB"]["estimate"].is_null());
    }
  for (const Json& p : r["wilcoxon"]["pairs"]) {
    EXPECT_TRUE(p["p"].is_null());
    EXPECT_NE(p["reason"].get<std::string>().find("fewer than 6"), std::string::npos);
  }
  // Without tests nothing is significantly different: all four models form one clique.
  ASSERT_EQ(r["wilcoxon"]["cliques"].size(), 1u);
  EXPECT_EQ(r["wilcoxon"]["cliques"][0].size(), 4u);
  expectNoNanOrInf(dir, res);
}

TEST(StudyAnalysis, AStudyWithoutImageErrorsStillWritesItsFilesAndSaysWhy) {
  TempDir dir;
  auto rows = syntheticStudy();
  for (auto& r : rows) r.rrmse.reset();
  const auto res = analyseStudy(rows, fastOptions(), dir.path());
  const Json r = results(dir);
  EXPECT_EQ(r["counts"]["rowsSkippedWithoutRrmse"], 96);
  EXPECT_TRUE(r["friedman"]["p"].is_null());
  EXPECT_FALSE(r["friedman"]["reason"].get<std::string>().empty());
  EXPECT_NE(res.summary.find("96 without rRMSE skipped"), std::string::npos) << res.summary;
  expectNoNanOrInf(dir, res);
}

TEST(StudyAnalysis, RowsThatCannotBeAStudyAreBadInput) {
  TempDir dir;
  auto rows = syntheticStudy();
  rows.push_back(rows[0]);
  rows.back().fit = "microfacet:E2:glossy";
  rows.back().rrmse.reset();  // even a row the statistics would skip
  const std::string twice = test::expectInputError([&] { analyseStudy(rows, fastOptions(), dir.path()); });
  EXPECT_NE(twice.find("appears twice"), std::string::npos) << twice;
  EXPECT_NE(twice.find("microfacet:E2:glossy"), std::string::npos) << twice;
  rows = syntheticStudy();
  rows[2].e1 = std::nan("");
  EXPECT_NE(test::expectInputError([&] { analyseStudy(rows, fastOptions(), dir.path()); }).find("E1"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(dir / "results.json"));
}

TEST(StudyPerceptual, ReadsTheReleasedTables) {
  GLOSSY_REQUIRE_SHARED("perceptual");
  const auto data = PerceptualData::read(test::sharedDir() / "perceptual");
  EXPECT_EQ(data.materialClass("alum-bronze"), "Metal");
  EXPECT_EQ(data.materialClass("aventurnine"), "Dielectric");
  EXPECT_EQ(data.materialClass("no-such-material"), "");
  // PerceptualDistances.csv line 2: "ABC";"alum-bronze";0.216666666666667
  EXPECT_NEAR(*data.distance("ABC", "alum-bronze"), 0.216666666666667, 1e-15);
  EXPECT_FALSE(data.distance("ABC", "no-such-material"));
  // Every MERL material of glossy's library has a class.
  for (const auto& entry : std::filesystem::directory_iterator(test::libraryDir() / "merl"))
    if (entry.path().extension() == ".toml") {
      EXPECT_NE(data.materialClass(entry.path().stem().string()), "") << entry.path();
    }
}

TEST(StudyPerceptual, MalformedTablesNameTheFileAndLine) {
  TempDir dir;
  test::writeText(dir / "MaterialType.csv", "BRDF;Type\nalum-bronze;Metal\n");
  test::writeText(dir / "PerceptualDistances.csv", "\"METHOD\";\"BRDF\";\"DISTANCE\"\n\"ABC\";\"alum-bronze\";0.2\n\"ABC\";\"x\";nan\n");
  std::string msg = test::expectInputError([&] { PerceptualData::read(dir.path()); });
  EXPECT_NE(msg.find("PerceptualDistances.csv:3"), std::string::npos) << msg;
  test::writeText(dir / "PerceptualDistances.csv", "\"METHOD\";\"BRDF\";\"DISTANCE\"\n\"ABC\";\"alum-bronze\";0.2\n");
  test::writeText(dir / "MaterialType.csv", "BRDF;Type\nalum-bronze;Metallic\n");
  msg = test::expectInputError([&] { PerceptualData::read(dir.path()); });
  EXPECT_NE(msg.find("MaterialType.csv:2"), std::string::npos) << msg;
  test::writeText(dir / "MaterialType.csv", "Material;Type\n");
  msg = test::expectInputError([&] { PerceptualData::read(dir.path()); });
  EXPECT_NE(msg.find("MaterialType.csv:1"), std::string::npos) << msg;
  std::filesystem::remove(dir / "MaterialType.csv");
  msg = test::expectInputError([&] { PerceptualData::read(dir.path()); });
  EXPECT_NE(msg.find("MaterialType.csv"), std::string::npos) << msg;
  // The analysis reads them before writing anything.
  TempDir out;
  AnalysisOptions o = fastOptions();
  o.perceptualDir = dir.path();
  test::expectInputError([&] { analyseStudy(syntheticStudy(), o, out.path()); });
  EXPECT_TRUE(std::filesystem::is_empty(out.path()));
}

TEST(StudyPerceptual, TheSharedFitsAreComparedWithPeople) {
  GLOSSY_REQUIRE_SHARED("perceptual");
  TempDir dir;
  AnalysisOptions o = fastOptions();
  o.perceptualDir = test::sharedDir() / "perceptual";
  const auto res = analyseStudy(syntheticStudy(), o, dir.path());
  const Json r = results(dir);
  const Json& fits = r["againstPeople"]["fits"];
  ASSERT_EQ(fits.size(), 2u);  // ABC against both published ABC fits: the variant is not documented
  for (const Json& f : fits) {
    EXPECT_EQ(f["method"], "ABC");
    EXPECT_EQ(f["materials"], 12);
    ASSERT_EQ(f["figures"].size(), 4u);
    EXPECT_FALSE(f["figures"][0]["spearman"]["estimate"].is_null());
    EXPECT_FALSE(f["agreesBest"].is_null());
  }
  EXPECT_NE(res.summary.find("agrees best with the perceived distance"), std::string::npos) << res.summary;
  EXPECT_TRUE(std::filesystem::exists(dir / "perceptual.svg"));
  EXPECT_NE(test::readText(dir / "summary.md").find("Lavoué"), std::string::npos);
  expectNoNanOrInf(dir, res);
}

}  // namespace
}  // namespace glossy::study

namespace glossy::study {

// The analysis tells each of its steps as it starts, in order: a study of a database takes minutes in its
// bootstraps, which would otherwise be silent.
TEST(StudyAnalysis, EachStepIsToldAsItStarts) {
  TempDir dir;
  AnalysisOptions o = fastOptions();
  std::vector<int> steps;
  o.progress = [&](int step, int of, const std::string& what) {
    EXPECT_EQ(of, 6);
    EXPECT_FALSE(what.empty());
    steps.push_back(step);
  };
  analyseStudy(syntheticStudy(), o, dir.path());
  EXPECT_EQ(steps, (std::vector<int>{1, 2, 3, 4, 5, 6}));
  EXPECT_GT(expectedAnalysisSeconds(1000000, 100, 6), 3600.0) << "a million resamples of a database take hours";
}

}  // namespace glossy::study
