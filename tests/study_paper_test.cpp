// A study's results as a paper cites them (docs/study.md, "Provenance and methods", "The files"): results.json
// records the glossy that made them and everything they stand on, the study file is kept beside them, a
// methods paragraph and LaTeX tables are generated and compile, rows print each figure to the precision it
// has, and the figures draw a clamped zero as a zero.
#include "renderer/report/study_page.h"
#include "renderer/study/study_analysis.h"
#include "renderer/study/study_latex.h"
#include "renderer/study/study_tables.h"
#include "renderer/util/build_info.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <regex>

namespace glossy::study {
namespace {

using test::TempDir;
using Json = nlohmann::json;
namespace fs = std::filesystem;

const std::vector<std::string> kMaterials = {"alum-bronze", "alumina-oxide", "aluminium", "aventurnine", "beige-fabric",
                                             "black-fabric", "black-obsidian", "black-oxidized-steel", "blue-acrylic", "blue-fabric"};

struct Model {
  std::string label, fit, source;
  double factor;
};
// Alphabetical order (AS, CT, Microfacet, Smooth) is not rank order (Microfacet, Smooth, CT, AS).
const std::vector<Model> kModels = {{"Microfacet E2", "microfacet:E2", "published", 0.5},
                                    {"Smooth E2", "smooth:E2", "published", 1.0},
                                    {"CT E1", "cook-torrance:E1:glossy", "glossy", 1.4},
                                    {"AS E2", "ashikhmin-shirley:E2", "published", 1.9}};

// 10 materials × 2 lightings × 4 models, every figure a float32 as the sheets store them.
std::vector<StudyRow> floatStudy() {
  std::vector<StudyRow> rows;
  std::uint64_t state = 99;
  const auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 11) / double(1ull << 53);
  };
  const auto f32 = [](double v) { return double(float(v)); };
  for (std::size_t i = 0; i < kMaterials.size(); ++i)
    for (const std::string lighting : {"sky", "studio"})
      for (const Model& m : kModels) {
        StudyRow r;
        r.material = kMaterials[i];
        r.database = i < 7 ? "MERL" : "RGL-EPFL";
        r.lighting = lighting;
        r.scene = "preview";
        r.layer = m.fit;
        r.label = m.label;
        r.fit = m.fit;
        r.fitMetric = m.fit.find("E1") != std::string::npos ? "E1" : "E2";
        r.fitSource = m.source;
        r.rrmse = f32(0.03 * (1.0 + 0.3 * double(i)) * m.factor * (1.0 + 0.1 * next()));
        r.rrmseLo = f32(*r.rrmse * 0.97);
        r.rrmseHi = f32(*r.rrmse * 1.03);
        r.flip = f32(0.1 + *r.rrmse);
        r.e1 = f32(0.02 + 0.05 * next());
        r.e2 = f32(0.01 * m.factor * (1.0 + 0.1 * double(i)));
        r.luminanceRatio = f32(1.0 + 0.01 * next());
        r.closest = m.label == "Microfacet E2";
        r.sheet = "sheets/preview/" + lighting + "/" + r.material + ".exr";
        r.width = r.height = 32;
        r.spp = 64;
        r.seed = 3;
        rows.push_back(r);
      }
  return rows;
}

const std::string kStudyText = "# the study file, kept as it was read\nmaterials = [\"merl/*\"]\n[settings]\nspp = 64\n";

StudyProvenance provenance() {
  StudyProvenance p;
  p.studyFile = "paper.toml";
  p.studyText = kStudyText;
  p.settings = {32, 32, 64, true, 0.0, 0.0, 3, 8, 4, 1, 0.0, "measured,microfacet:E2,smooth:E2", false, 300, "Microfacet E2"};
  p.lightings = {{"sky", "sky", "default sky", "", "", 0.0},
                 {"studio", "map", "studio_small_09_1k.hdr rotated 90°", "studio_small_09_1k.hdr", "0123456789abcdef", 90.0}};
  p.scenes = {{"preview", "preview", "preview.gltf", "", "fedcba9876543210"}};
  for (std::size_t i = 0; i < kMaterials.size(); ++i)
    p.materials.push_back({kMaterials[i], i < 7 ? "MERL" : "RGL-EPFL", i < 7 ? "MERL table" : "NBRDF reconstruction",
                           i < 7 ? "MERL" : "RGL-EPFL (NBRDF reconstruction)", "00000000000000" + std::to_string(10 + i)});
  return p;
}

AnalysisOptions options() {
  AnalysisOptions o;
  o.resamples = 300;
  o.seed = 3;
  o.provenance = provenance();
  return o;
}

Json results(const TempDir& dir) { return Json::parse(test::readText(dir / "results.json")); }

// The significant digits of a number's text: "0.0123" has 3, "1.5e-05" 2.
int significantDigits(const std::string& text) {
  std::string mantissa = text.substr(0, text.find_first_of("eE"));
  mantissa.erase(std::remove_if(mantissa.begin(), mantissa.end(), [](char c) { return c == '.' || c == '-' || c == '+'; }), mantissa.end());
  const auto first = mantissa.find_first_not_of('0');
  return first == std::string::npos ? 1 : int(mantissa.size() - first);
}

TEST(StudyPaper, RowsPrintEachFloat32FigureShortAndExact) {
  TempDir dir;
  const auto rows = floatStudy();
  analyseStudy(rows, options(), dir.path());
  const auto csv = test::readCsv(dir / "rows.csv");
  const Json json = Json::parse(test::readText(dir / "rows.json"));
  ASSERT_EQ(csv.size(), rows.size());
  ASSERT_EQ(json.size(), rows.size());
  // rows.csv is in the analysis's order (material, lighting, scene, label): match each row by its keys.
  int checked = 0;
  for (std::size_t k = 0; k < csv.size(); ++k) {
    const auto& c = csv[k];
    const auto it = std::find_if(rows.begin(), rows.end(), [&](const StudyRow& r) {
      return r.material == c.at("material") && r.lighting == c.at("lighting") && r.label == c.at("label");
    });
    ASSERT_NE(it, rows.end());
    for (const auto& [column, key, value] : {std::tuple{"rrmse", "rrmse", *it->rrmse}, {"rrmse_hi", "rrmseHi", *it->rrmseHi},
                                             {"e1", "e1", *it->e1}, {"luminance_ratio", "luminanceRatio", *it->luminanceRatio}}) {
      const std::string text = c.at(column);
      EXPECT_LE(significantDigits(text), 9) << column << " printed as " << text;
      float read = 0.0f;
      std::from_chars(text.data(), text.data() + text.size(), read);
      EXPECT_EQ(read, float(value)) << column << " " << text << " does not read back as the float32 it was";
      EXPECT_EQ(float(json[k][key].get<double>()), float(value)) << key;
      EXPECT_LE(significantDigits(json[k][key].dump()), 9) << key << " in rows.json: " << json[k][key].dump();
      ++checked;
    }
  }
  EXPECT_EQ(checked, int(4 * rows.size()));
}

TEST(StudyPaper, ResultsRecordTheGlossyTheSettingsTheInputsAndTheFits) {
  TempDir dir;
  analyseStudy(floatStudy(), options(), dir.path());
  const Json r = results(dir);
  EXPECT_EQ(r["glossy"]["version"], GLOSSY_VERSION);
  EXPECT_EQ(r["glossy"]["commit"], std::string(glossyCommit()));
  EXPECT_FALSE(r["glossy"]["commit"].get<std::string>().empty());
  const Json& p = r["provenance"];
  EXPECT_EQ(p["studyFile"], "paper.toml");
  const Json& s = p["settings"];
  EXPECT_EQ(s["width"], 32);
  EXPECT_EQ(s["spp"], 64);
  EXPECT_EQ(s["seed"], 3);
  EXPECT_EQ(s["maxDepth"], 8);
  EXPECT_EQ(s["lightSamples"], 4);
  EXPECT_EQ(s["panels"], "measured,microfacet:E2,smooth:E2");
  EXPECT_EQ(s["resamples"], 300);
  ASSERT_EQ(p["lightings"].size(), 2u);
  EXPECT_EQ(p["lightings"][1]["map"], "studio_small_09_1k.hdr");
  EXPECT_EQ(p["lightings"][1]["digest"], "0123456789abcdef");
  EXPECT_EQ(p["lightings"][1]["rotate"], 90.0);
  EXPECT_EQ(p["scenes"][0]["digest"], "fedcba9876543210");
  ASSERT_EQ(p["databases"].size(), 2u);
  EXPECT_EQ(p["databases"][0]["database"], "MERL");
  EXPECT_EQ(p["databases"][0]["measured"]["MERL table"], 7);
  EXPECT_EQ(p["databases"][1]["measured"]["NBRDF reconstruction"], 3);
  // Each model's fits by source: CT E1 is glossy's own.
  for (const Json& m : r["fits"]) {
    ASSERT_EQ(m["fits"].size(), 1u) << m.dump();
    EXPECT_EQ(m["fits"][0]["source"], m["model"] == "CT E1" ? "glossy" : "published") << m.dump();
    EXPECT_EQ(m["fits"][0]["materials"], 10);
  }
  // The study file beside its results, byte for byte.
  EXPECT_EQ(test::readText(dir / "study.toml"), kStudyText);
  // Without a study file: said, and nothing copied.
  TempDir bare;
  AnalysisOptions o = options();
  o.provenance.reset();
  analyseStudy(floatStudy(), o, bare.path());
  EXPECT_FALSE(results(bare)["provenance"]["reason"].get<std::string>().empty());
  EXPECT_FALSE(fs::exists(bare / "study.toml"));
}

TEST(StudyPaper, TheMethodsParagraphSaysWhatWasRenderedAndHowItWasTested) {
  TempDir dir;
  analyseStudy(floatStudy(), options(), dir.path());
  const std::string md = test::readText(dir / "summary.md");
  const auto methods = md.find("## Methods");
  ASSERT_NE(methods, std::string::npos) << md;
  const std::string text = md.substr(methods);
  for (const std::string& said :
       {std::string("10 measured materials"), std::string("7 from MERL (measured tables)"), std::string("3 from RGL-EPFL (NBRDF reconstructions)"),
        std::string("the environment map studio_small_09_1k.hdr rotated by 90 degrees"), std::string("glossy " GLOSSY_VERSION " (commit ") + std::string(glossyCommit()),
        std::string("CT E1 (glossy's own fit)"), std::string("32 × 32 pixels at 64 samples per pixel"), std::string("seed 3"),
        std::string("Friedman test"), std::string("Iman–Davenport"), std::string("Wilcoxon signed-rank"), std::string("Holm-corrected"),
        std::string("percentile bootstrap"), std::string("300 resamples")})
    EXPECT_NE(text.find(said), std::string::npos) << "the methods do not say \"" << said << "\":\n" << text;
  const std::string tex = test::readText(dir / "methods.tex");
  EXPECT_NE(tex.find("32 $\\times$ 32 pixels"), std::string::npos) << tex;
  EXPECT_NE(tex.find("95 \\% percentile bootstrap"), std::string::npos) << tex;
}

TEST(StudyPaper, ModelsTexIsATableInRankOrderWithGroupsAndEffectSizes) {
  TempDir dir;
  analyseStudy(floatStudy(), options(), dir.path());
  const Json r = results(dir);
  const std::string tex = test::readText(dir / "models.tex");
  for (const char* part : {"\\begin{table}", "\\caption{", "\\label{tab:glossy-study-models}", "\\label{tab:glossy-study-closer}", "Group",
                           "Closer than next"})
    EXPECT_NE(tex.find(part), std::string::npos) << part << "\n" << tex;
  // The rows in order of mean rank, as results.json gives it.
  std::vector<std::pair<double, std::string>> ranks;
  for (const Json& m : r["models"]) ranks.emplace_back(m["meanRank"].get<double>(), m["label"].get<std::string>());
  std::sort(ranks.begin(), ranks.end());
  std::size_t at = 0;
  for (const auto& [rank, label] : ranks) {
    const auto row = tex.find("\n" + label + " & ", at);
    ASSERT_NE(row, std::string::npos) << label << " is not after the models ranked ahead of it:\n" << tex;
    at = row + 1;
  }
  EXPECT_EQ(ranks.front().second, "Microfacet E2");
  EXPECT_NE(tex.find("glossy's own fits: CT E1; the others are the published fits."), std::string::npos) << tex;
  // Every pair separated here (each material orders the models alike): one letter per model, and the best
  // model is closer than the next on every material.
  EXPECT_NE(tex.find("\nMicrofacet E2 & a & "), std::string::npos) << tex;
  EXPECT_NE(tex.find("\nAS E2 & d & "), std::string::npos) << tex;
  // A share every resample puts at 1 has no interval (study_intervals.h), and the caption says why.
  EXPECT_NE(tex.find("& 1.00 \\\\"), std::string::npos) << tex;
  EXPECT_EQ(tex.find("[1.00, 1.00]"), std::string::npos) << tex;
  EXPECT_NE(tex.find("Figures without an interval have none: every resample gives 1"), std::string::npos) << tex;
  // A clique: models the tests do not separate share a letter.
  Json cliqued = r;
  cliqued["wilcoxon"]["cliques"] = Json::array({Json::array({"Smooth E2", "CT E1"}), Json::array({"CT E1", "AS E2"})});
  const std::vector<std::string> order = modelsByRank(nlohmann::ordered_json(cliqued));
  EXPECT_EQ(order, (std::vector<std::string>{"Microfacet E2", "Smooth E2", "CT E1", "AS E2"}));
  EXPECT_EQ(groupLetters(nlohmann::ordered_json(cliqued), order), (std::vector<std::string>{"a", "b", "b,c", "c"}));
}

TEST(StudyPaper, LatexEscapesWhatNamesCanHold) {
  EXPECT_EQ(latexEscape("a_b & 50% #1 $x {y} ~^\\"), "a\\_b \\& 50\\% \\#1 \\$x \\{y\\} \\textasciitilde{}\\textasciicircum{}\\textbackslash{}");
  EXPECT_EQ(latexEscape("90° Löw"), "90\\textdegree{} L\\\"{o}w");
  EXPECT_EQ(latexEscape("漢"), "?");
  EXPECT_EQ(latexEscape("<a|b>"), "\\textless{}a\\textbar{}b\\textgreater{}");
}

// The generated LaTeX compiles: models.tex and methods.tex \input into a document, with a model's label
// holding LaTeX's special characters.
TEST(StudyPaper, TheGeneratedLatexCompilesWithPdflatex) {
  if (std::system("command -v pdflatex >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "pdflatex is not installed (texlive-latex-base, a test package of scripts/test)";
  TempDir dir;
  auto rows = floatStudy();
  for (StudyRow& row : rows)
    if (row.label == "AS E2") row.label = "AS_E2 & 50% #1";
  analyseStudy(rows, options(), dir.path());
  // booktabs is texlive-latex-recommended's: without it its three rules stand in as \hline.
  test::writeText(dir / "paper.tex",
                  "\\documentclass{article}\n\\usepackage[margin=1cm,landscape]{geometry}\n"
                  "\\IfFileExists{booktabs.sty}{\\usepackage{booktabs}}{\\newcommand{\\toprule}{\\hline}\\newcommand{\\midrule}{\\hline}"
                  "\\newcommand{\\bottomrule}{\\hline}}\n"
                  "\\begin{document}\n\\input{models.tex}\n\\input{methods.tex}\nTable~\\ref{tab:glossy-study-models}.\n\\end{document}\n");
  const std::string command = "cd " + test::shellQuote(dir.path().string()) +
                              " && pdflatex -interaction=nonstopmode -halt-on-error paper.tex > pdflatex.log 2>&1";
  const int status = std::system(command.c_str());
  EXPECT_EQ(status, 0) << test::readText(dir / "pdflatex.log");
  EXPECT_TRUE(fs::exists(dir / "paper.pdf"));
  const std::string log = test::readText(dir / "pdflatex.log");
  EXPECT_EQ(log.find("Missing character"), std::string::npos) << log;
}

TEST(StudyPaper, FiguresDrawAClampedZeroAsAZeroWithSolidLinesAndCaptions) {
  TempDir dir;
  auto rows = floatStudy();
  for (StudyRow& row : rows)
    if (row.material == "aluminium" && row.label == "Microfacet E2") row.rrmse = 0.0;  // a negative estimate, clamped
  analyseStudy(rows, options(), dir.path());
  const std::string heat = test::readText(dir / "heat_map.svg");
  EXPECT_EQ(heat.find("fill=\"#dddddd\""), std::string::npos) << "a zero painted as not rendered";
  EXPECT_NE(heat.find(">0</text>"), std::string::npos) << "the zero is not marked";
  const std::string curves = test::readText(dir / "error_curves.svg");
  EXPECT_NE(curves.find("<circle"), std::string::npos) << "the zero is not drawn as a point";
  EXPECT_EQ(curves.find("stroke-dasharray"), std::string::npos) << "a dashed line (CT E1 is glossy's fit)";
  EXPECT_NE(curves.find("glossy&apos;s fit"), std::string::npos) << "the legend does not say whose fit CT E1 is";
  // Every figure's caption in results.json and summary.md.
  const Json r = results(dir);
  const std::string md = test::readText(dir / "summary.md");
  ASSERT_FALSE(r["figures"].empty());
  for (const Json& f : r["figures"]) {
    ASSERT_TRUE(f["caption"].is_string()) << f.dump();
    EXPECT_NE(md.find("- `" + f["name"].get<std::string>() + ".svg`: "), std::string::npos) << f["name"];
  }
  // Without a zero the curves carry no circle.
  TempDir plain;
  analyseStudy(floatStudy(), options(), plain.path());
  EXPECT_EQ(test::readText(plain / "error_curves.svg").find("<circle"), std::string::npos);
}

TEST(StudyPaper, TheReportPageCaptionsEachFigureAsTheAnalysisDoes) {
  StudyPlan plan;
  plan.lightings = {"sky"};
  plan.scenes = {"preview"};
  report::StudyFiles files;
  files.figures = {"heat_map.svg"};
  files.captions["heat_map"] = "The caption the analysis wrote.";
  const std::string page = report::studyPage(plan, {}, files);
  EXPECT_NE(page.find("<figcaption>The caption the analysis wrote."), std::string::npos) << page;
}

TEST(StudyPaper, TheProgramSaysItsCommit) {
  const std::string commit(glossyCommit());
  ASSERT_FALSE(commit.empty());
  if (fs::exists(test::sourceDir() / ".git")) {
    EXPECT_NE(commit, "unknown") << "built from a git checkout, the commit is known";
    EXPECT_TRUE(std::regex_match(commit, std::regex("[0-9a-f]{12}(-dirty)?|.*-g[0-9a-f]{12}(-dirty)?"))) << commit;
  }
  const test::RunResult r = test::runGlossy({"--version"});
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find(std::string(GLOSSY_VERSION) + " (" + commit + ")"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace glossy::study
