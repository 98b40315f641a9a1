// Which approximation looks closest, glossy against people, within a material (renderer/study/study_people.h),
// on made-up perceived distances (never the dataset's) and rows built so that every answer is known: r*
// orders the approximations as people do, E1 the reverse, ꟻLIP on one lighting only, ΔE_ITP and SSIM (a
// similarity) as people do.
#include "renderer/study/study_people.h"
#include "materials/core/text.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace glossy::study {
namespace {

using test::TempDir;
using Json = nlohmann::ordered_json;

struct Approximation {
  const char* method;
  const char* fit;
  const char* label;
};
// The dataset's methods and the fits their rows judge (perceptual.h), ABC both ways.
const Approximation kApproximations[] = {{"ABC", "microfacet:E2", "Microfacet E2"}, {"ABC", "smooth:E2", "Smooth E2"},
                                         {"WARD", "ward:Ngan05", "Ward Ngan05"},     {"BLINN-PHONG", "blinn-phong:Ngan05", "BP Ngan05"},
                                         {"LAFORTUNE", "lafortune:Ngan05", "Lafortune Ngan05"}, {"SGD", "sgd:Bagher12", "SGD Bagher12"}};
constexpr int kMaterials = 12;

std::string material(int i) { return "material-" + std::to_string(i); }
// People's distance: a different closest approximation from material to material.
double distance(int i, int a) { return 0.1 + 0.1 * double((a + i) % 6); }

struct Fixture {
  TempDir dir;
  std::vector<StudyRow> rows;
  PerceptualData data;

  Fixture() {
    std::string csv = "\"METHOD\";\"BRDF\";\"DISTANCE\"\n";
    for (int i = 0; i < kMaterials; ++i)
      for (int a = 0; a < 6; ++a)
        // ABC has one row per material: the Microfacet variant's distance (a = 0).
        if (a != 1) csv += "\"" + std::string(kApproximations[a].method) + "\";\"" + material(i) + "\";" + std::to_string(distance(i, a)) + "\n";
    test::writeText(dir.path() / "PerceptualDistances.csv", csv);
    test::writeText(dir.path() / "MaterialType.csv", "BRDF;Type\nmaterial-0;Metal\n");
    data = PerceptualData::read(dir.path());
    for (int i = 0; i < kMaterials; ++i)
      for (const char* lighting : {"sky", "studio"})
        for (int a = 0; a < 6; ++a) {
          StudyRow r;
          r.material = material(i);
          r.lighting = lighting;
          r.scene = "ball";
          r.fit = kApproximations[a].fit;
          r.label = kApproximations[a].label;
          r.fitSource = "published";
          const double d = distance(i, a == 1 ? 0 : a) + (a == 1 ? 0.05 : 0.0);  // Smooth: just behind Microfacet
          r.rrmse = d * (lighting == std::string("sky") ? 1.0 : 2.0);  // people's order under both lightings
          r.e1 = 1.0 - d;                                              // the reverse
          r.e2 = 0.5;                                                  // no order at all
          r.flip = lighting == std::string("sky") ? d : 1.0 - d;       // people's order under the sky only
          r.deltaEItp = 10.0 * d;                                      // people's order
          r.ssim = 1.0 - d;                                            // a similarity: people's order as 1 − SSIM
          rows.push_back(r);
        }
  }

  std::vector<const StudyRow*> used() const {
    std::vector<const StudyRow*> out;
    for (const StudyRow& r : rows) out.push_back(&r);
    return out;
  }
};

const Json& figure(const Json& block, const std::string& name) {
  for (const Json& f : block["figures"])
    if (f["figure"] == name) return f;
  throw std::runtime_error("no figure " + name);
}

TEST(StudyPeople, AFigureThatOrdersTheApproximationsAsPeopleDoAgreesFullyAndItsReverseNotAtAll) {
  const Fixture fx;
  const PeopleAnalysis p = closestToPeople(fx.used(), fx.data, 400, 1);
  const Json& microfacet = p.json["variants"][0];
  ASSERT_EQ(microfacet["abc"], "microfacet:E2");
  const Json& rrmse = figure(microfacet["overall"], "rrmse");
  EXPECT_EQ(rrmse["materials"], kMaterials);
  EXPECT_DOUBLE_EQ(rrmse["closestAgrees"]["estimate"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(rrmse["meanKendallTau"]["estimate"].get<double>(), 1.0);
  EXPECT_GT(rrmse["pooledSpearman"]["estimate"].get<double>(), 0.95);
  EXPECT_DOUBLE_EQ(rrmse["chance"]["closestAgrees"].get<double>(), 0.2);
  const Json& e1 = figure(microfacet["overall"], "e1");
  EXPECT_DOUBLE_EQ(e1["closestAgrees"]["estimate"].get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(e1["meanKendallTau"]["estimate"].get<double>(), -1.0);
  // E2 ties every approximation: each material's share is that of a random pick among five, 1/5.
  EXPECT_DOUBLE_EQ(figure(microfacet["overall"], "e2")["closestAgrees"]["estimate"].get<double>(), 0.2);
  EXPECT_TRUE(figure(microfacet["overall"], "e2")["meanKendallTau"]["estimate"].is_null());
  EXPECT_EQ(microfacet["overall"]["agreesBest"], "rrmse");
  // SSIM is a similarity: its closest is its largest, so it agrees as fully as ΔE_ITP does.
  for (const char* name : {"deltaEItp", "ssim"}) {
    EXPECT_DOUBLE_EQ(figure(microfacet["overall"], name)["closestAgrees"]["estimate"].get<double>(), 1.0) << name;
    EXPECT_DOUBLE_EQ(figure(microfacet["overall"], name)["meanKendallTau"]["estimate"].get<double>(), 1.0) << name;
  }
  // ꟻLIP agrees under the sky and is reversed under the studio: the per-lighting blocks say so.
  EXPECT_DOUBLE_EQ(figure(microfacet["byLighting"]["sky"], "flip")["closestAgrees"]["estimate"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(figure(microfacet["byLighting"]["studio"], "flip")["closestAgrees"]["estimate"].get<double>(), 0.0);
  EXPECT_NE(p.headline.find("12 materials): rrmse names people's closest for 1.00"), std::string::npos) << p.headline;
  EXPECT_NE(p.headline.find("(chance 0.20)"), std::string::npos) << p.headline;
}

TEST(StudyPeople, EachAbcVariantIsAskedAndTheEvidenceCountsWhatTheDatasetCovers) {
  Fixture fx;
  // Material 3 has no SGD row: it drops out of every comparison, which needs all five.
  std::erase_if(fx.rows, [](const StudyRow& r) { return r.material == material(3) && r.fit == std::string("sgd:Bagher12"); });
  const PeopleAnalysis p = closestToPeople(fx.used(), fx.data, 400, 1);
  ASSERT_EQ(p.json["variants"].size(), 2u);
  EXPECT_EQ(p.json["variants"][1]["abc"], "smooth:E2");
  EXPECT_EQ(figure(p.json["variants"][0]["overall"], "rrmse")["materials"], kMaterials - 1);
  // Smooth E2 is just behind Microfacet E2 in r*, so where ABC is people's closest it is r*'s too.
  EXPECT_DOUBLE_EQ(figure(p.json["variants"][1]["overall"], "rrmse")["closestAgrees"]["estimate"].get<double>(), 1.0);
  for (const Json& e : p.json["evidence"]) {
    EXPECT_EQ(e["datasetMaterials"], kMaterials) << e.dump();
    EXPECT_EQ(e["studyMaterialsWithFit"], e["fit"] == "sgd:Bagher12" ? kMaterials - 1 : kMaterials) << e.dump();
    EXPECT_EQ(e["ofThemJudged"], e["studyMaterialsWithFit"]) << e.dump();
  }
  // Deterministic for a seed, whatever the order of the rows.
  std::vector<const StudyRow*> reversed = fx.used();
  std::reverse(reversed.begin(), reversed.end());
  EXPECT_EQ(closestToPeople(reversed, fx.data, 400, 1).json.dump(), p.json.dump());
}

TEST(StudyPeople, ATieBetweenGlossysClosestIsSharedNotCountedWhole) {
  Fixture fx;
  // Material 0: r* ties people's closest with one other approximation.
  int tiedWith = -1;
  for (int a = 2; a < 6; ++a)
    if (distance(0, a) > distance(0, 0) + 0.05) {
      tiedWith = a;
      break;
    }
  ASSERT_GE(tiedWith, 0);
  const double closestDistance = [&] {
    double low = 1e9;
    for (int a = 0; a < 6; ++a)
      if (a != 1) low = std::min(low, distance(0, a));
    return low;
  }();
  for (StudyRow& r : fx.rows)
    if (r.material == material(0) && r.fit == std::string(kApproximations[tiedWith].fit))
      r.rrmse = closestDistance * (r.lighting == "sky" ? 1.0 : 2.0);
  const PeopleAnalysis p = closestToPeople(fx.used(), fx.data, 400, 1);
  // Eleven materials agree fully, the tied one half.
  EXPECT_NEAR(figure(p.json["variants"][0]["overall"], "rrmse")["closestAgrees"]["estimate"].get<double>(), (11.0 + 0.5) / 12.0, 1e-12);
}

// The summary's section and people.tex print what results.json holds, per ABC variant, overall and per
// lighting; the LaTeX compiles.
TEST(StudyPeople, TheTablesShowTheJsonsFiguresAndTheLatexCompiles) {
  const Fixture fx;
  const PeopleAnalysis p = closestToPeople(fx.used(), fx.data, 400, 1);
  EXPECT_NE(p.markdown.find("### ABC as microfacet:E2"), std::string::npos) << p.markdown;
  EXPECT_NE(p.markdown.find("### ABC as smooth:E2"), std::string::npos) << p.markdown;
  const Json& flip = figure(p.json["variants"][0]["overall"], "flip");
  const std::string share = formatted("%.2f", flip["closestAgrees"]["estimate"].get<double>());
  EXPECT_NE(p.markdown.find("| ꟻLIP | " + share), std::string::npos) << p.markdown;
  EXPECT_NE(p.markdown.find("| figure | sky | studio |"), std::string::npos) << p.markdown;
  EXPECT_NE(p.markdown.find("| ꟻLIP | 1.00"), std::string::npos) << "under the sky ꟻLIP orders as people do\n" << p.markdown;
  EXPECT_NE(p.markdown.find("| 1 − SSIM | 1.00"), std::string::npos) << p.markdown;
  EXPECT_NE(p.tex.find("\\label{tab:glossy-study-people-microfacet-E2}"), std::string::npos) << p.tex;
  if (std::system("command -v pdflatex >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "pdflatex is not installed (texlive-latex-base, a test package of scripts/test)";
  test::writeText(fx.dir / "people.tex", p.tex);
  test::writeText(fx.dir / "paper.tex", "\\documentclass{article}\n\\begin{document}\n\\input{people.tex}\n\\end{document}\n");
  const std::string command = "cd " + test::shellQuote(fx.dir.path().string()) +
                              " && pdflatex -interaction=nonstopmode -halt-on-error paper.tex > pdflatex.log 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0) << test::readText(fx.dir / "pdflatex.log");
  EXPECT_EQ(test::readText(fx.dir / "pdflatex.log").find("Missing character"), std::string::npos);
}

// A study without every judged fit (the supplement's grid has no Ngan or Bagher fit) says so in one sentence
// per variant, with no tables of nothing and no people.tex.
TEST(StudyPeople, WithoutEveryJudgedFitThereAreNoTables) {
  Fixture fx;
  std::erase_if(fx.rows, [](const StudyRow& r) { return r.fit == std::string("sgd:Bagher12"); });
  const PeopleAnalysis p = closestToPeople(fx.used(), fx.data, 100, 1);
  EXPECT_TRUE(p.tex.empty()) << p.tex;
  EXPECT_EQ(p.markdown.find("| figure |"), std::string::npos) << p.markdown;
  EXPECT_NE(p.markdown.find("No material has a figure and a perceived distance for every approximation"), std::string::npos);
}

}  // namespace
}  // namespace glossy::study
