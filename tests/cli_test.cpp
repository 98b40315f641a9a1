// The glossy command as the interface contract states it: eval (test vectors, --pdf), import (the
// committed library regenerates byte for byte), exit status 2 with one line naming the file for bad input.
#include "materials/params/material_file.h"
#include "renderer/sheet/comparison_grid.h"
#include "tests/support/test_support.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <cmath>

namespace glossy::test {

namespace {

std::vector<std::vector<double>> parseOutput(const std::string& out) {
  std::vector<std::vector<double>> rows;
  std::istringstream in(out);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

std::string directions(const std::vector<std::map<std::string, std::string>>& rows) {
  std::string in;
  for (const auto& r : rows)
    in += r.at("Lx") + "," + r.at("Ly") + "," + r.at("Lz") + "," + r.at("Vx") + "," + r.at("Vy") + "," + r.at("Vz") + "\n";
  return in;
}

}  // namespace

TEST(CliEval, ReproducesEveryAnalyticTestVector) {
  GLOSSY_REQUIRE_SHARED("testvectors/brdf_eval.csv");
  std::map<std::pair<std::string, std::string>, std::vector<std::map<std::string, std::string>>> groups;
  for (const auto& r : readCsv(sharedDir() / "testvectors/brdf_eval.csv"))
    if (r.at("fit") != "measured") groups[{r.at("material"), r.at("fit")}].push_back(r);
  ASSERT_EQ(groups.size(), 36u);
  for (const auto& [key, rows] : groups) {
    const RunResult r = runGlossy({"eval", "--material", (materialsDir() / (key.first + ".toml")).string(), "--fit", key.second},
                                  directions(rows));
    ASSERT_EQ(r.status, 0) << r.err;
    const auto got = parseOutput(r.out);
    ASSERT_EQ(got.size(), rows.size());
    for (size_t i = 0; i < rows.size(); ++i) {
      ASSERT_EQ(got[i].size(), 3u);
      for (int c = 0; c < 3; ++c) {
        const double want = std::stod(rows[i].at(std::string(1, "RGB"[c])));
        EXPECT_NEAR(got[i][c], want, std::max(1e-5 * std::abs(want), 1e-12)) << key.first << " " << key.second;
      }
    }
  }
}

TEST(CliEval, ReproducesTheMeasuredTestVectorsFromTheCompressedTable) {
  GLOSSY_REQUIRE_SHARED("testvectors/brdf_eval.csv");
  GLOSSY_REQUIRE_SHARED("merl/blue-rubber.binary.xz");
  std::vector<std::map<std::string, std::string>> rows;
  for (const auto& r : readCsv(sharedDir() / "testvectors/brdf_eval.csv"))
    if (r.at("fit") == "measured") rows.push_back(r);
  const RunResult r = runGlossy({"eval", "--measured", (sharedDir() / "merl/blue-rubber.binary.xz").string()}, directions(rows));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto got = parseOutput(r.out);
  ASSERT_EQ(got.size(), rows.size());
  size_t exact = 0;
  for (size_t i = 0; i < rows.size(); ++i)
    exact += got[i] == std::vector<double>{std::stod(rows[i].at("R")), std::stod(rows[i].at("G")), std::stod(rows[i].at("B"))};
  EXPECT_GE(exact, rows.size() - 2) << "only bin-edge rows may differ (see TestVectors.MeasuredRowsThroughTheApi)";
}

// The embedded network evaluates (and samples) as shared/merl's table of it: the same test-vector rows.
TEST(CliEval, TheEmbeddedNetworkIsItsReconstructedTable) {
  GLOSSY_REQUIRE_SHARED("testvectors/brdf_eval.csv");
  GLOSSY_REQUIRE_SHARED("merl/blue-rubber.binary.xz");
  std::vector<std::map<std::string, std::string>> rows;
  for (const auto& r : readCsv(sharedDir() / "testvectors/brdf_eval.csv"))
    if (r.at("fit") == "measured") rows.push_back(r);
  const RunResult table = runGlossy({"eval", "--pdf", "--measured", (sharedDir() / "merl/blue-rubber.binary.xz").string()}, directions(rows));
  const RunResult network = runGlossy({"eval", "--pdf", "--measured", (materialsDir() / "blue-rubber.nbrdf").string()}, directions(rows));
  ASSERT_EQ(network.status, 0) << network.err;
  ASSERT_FALSE(rows.empty());
  EXPECT_EQ(parseOutput(network.out), parseOutput(table.out));
}

TEST(CliEval, PdfColumnIsTheSamplersDensity) {
  const auto file = materialsDir() / "gold-paint.toml";
  const RunResult r = runGlossy({"eval", "--material", file.string(), "--fit", "cook-torrance:E2", "--pdf"},
                                "0,0,1,0,0,1\n0.6,0,0.8,-0.6,0,0.8\n 0.3 , 0.4 , 0 , 0,0,1\n0,0,2,0,0,3\n");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto got = parseOutput(r.out);
  ASSERT_EQ(got.size(), 4u);
  const Brdf brdf = makeBrdf(*loadMaterialFile(file).find(FitId::parse("cook-torrance:E2", "test")));
  EXPECT_DOUBLE_EQ(got[0][3], pdf(brdf, Vec3(0, 0, 1), Vec3(0, 0, 1)));
  EXPECT_DOUBLE_EQ(got[1][3], pdf(brdf, Vec3(0.6, 0, 0.8), Vec3(-0.6, 0, 0.8)));
  EXPECT_GT(got[1][3], 0.8 / M_PI) << "the mirror direction is sampled more often than by the cosine lobe";
  EXPECT_EQ(got[2][3], 0.0) << "no density on the horizon";
  EXPECT_EQ(got[3], got[0]) << "directions are normalised";
}

TEST(CliEval, BadInputExitsTwoWithOneLineNamingTheFile) {
  TempDir tmp;
  writeText(tmp / "broken.toml", "name = \"x\"\n[[fit]]\nmodel = \"cook-torrance\"\nmetric = \"E1\"\nkd = [0,0,0]\nks = [1,1,1]\nm = -1\neta = 1.5\n");
  expectOneLineError(runGlossy({"eval", "--material", (tmp / "broken.toml").string(), "--fit", "cook-torrance:E1"}, "0,0,1,0,0,1\n"),
                     "broken.toml:7: fit 1 (cook-torrance:E1): key 'm': must be in [0.0001, 10]");
  writeText(tmp / "truncated.binary", std::string(1000, '\0'));
  expectOneLineError(runGlossy({"eval", "--measured", (tmp / "truncated.binary").string()}, "0,0,1,0,0,1\n"), "truncated.binary");
  const std::string good = (materialsDir() / "chrome.toml").string();
  expectOneLineError(runGlossy({"eval", "--material", good, "--fit", "cook-torrance:E1"}, "0,0,1,0,0,1\n0,0,1,0,x\n"), "stdin line 2");
  expectOneLineError(runGlossy({"eval", "--material", good, "--fit", "cook-torrance:E1"}, "0,0,0,0,0,1\n"), "stdin line 1: a direction is zero");
  expectOneLineError(runGlossy({"eval", "--material", good, "--fit", "lambertian:E1"}), "has no lambertian:E1 fit");
  expectOneLineError(runGlossy({"eval", "--material", good, "--fit", "phong:E1"}), "unknown model 'phong'");
  expectOneLineError(runGlossy({"eval", "--material", (tmp / "absent.toml").string(), "--fit", "smooth:E2"}), "absent.toml");
  expectOneLineError(runGlossy({"eval", "--measured", (tmp / "absent.binary").string()}), "absent.binary");
  writeText(tmp / "broken.nbrdf", "format = \"glossy-nbrdf 1\"\nmaterial = \"x\"\nlabel = \"x\"\ninput = \"half-difference\"\noutput = \"expm1\"\n[[layer]]\ninputs = 6\n");
  expectOneLineError(runGlossy({"eval", "--measured", (tmp / "broken.nbrdf").string()}, "0,0,1,0,0,1\n"), "broken.nbrdf:6: layer 1: key 'outputs' is missing");
}

TEST(CliSample, SamplesAgreeWithEvalAndArePerSeedDeterministic) {
  const std::string file = (materialsDir() / "alum-bronze.toml").string();
  const std::vector<std::string> args = {"sample", "--material", file, "--fit", "microfacet:E2", "--wo", "0.5,0,0.866", "-n", "200", "--seed", "4"};
  const RunResult r = runGlossy(args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(runGlossy(args).out, r.out) << "same seed, same samples";
  auto other = args;
  other.back() = "5";
  EXPECT_NE(runGlossy(other).out, r.out);
  const auto rows = parseOutput(r.out);
  ASSERT_EQ(rows.size(), 200u);
  // Feed the valid directions back through eval --pdf (at full precision): pdf and ρ·cos/pdf must match.
  std::vector<std::vector<double>> valid;
  for (const auto& row : rows) {
    ASSERT_EQ(row.size(), 7u);
    if (row[3] != 0.0) valid.push_back(row);
  }
  ASSERT_GT(valid.size(), 150u);
  std::string pairs;
  for (const auto& row : valid) {
    std::ostringstream line;
    line.precision(17);
    line << row[0] << "," << row[1] << "," << row[2] << ",0.5,0,0.866\n";
    pairs += line.str();
  }
  const RunResult e = runGlossy({"eval", "--material", file, "--fit", "microfacet:E2", "--pdf"}, pairs);
  ASSERT_EQ(e.status, 0) << e.err;
  const auto evals = parseOutput(e.out);
  ASSERT_EQ(evals.size(), valid.size());
  for (size_t i = 0; i < valid.size(); ++i) {
    EXPECT_NEAR(evals[i][3], valid[i][3], 1e-9 * valid[i][3]);
    const double cosL = valid[i][2] / std::sqrt(valid[i][0] * valid[i][0] + valid[i][1] * valid[i][1] + valid[i][2] * valid[i][2]);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(valid[i][4 + c], evals[i][c] * cosL / valid[i][3], 1e-7 * valid[i][4 + c] + 1e-12);
  }
}

TEST(CliSample, InvalidSamplesAndBadInput) {
  const std::string file = (materialsDir() / "chrome.toml").string();
  const RunResult below = runGlossy({"sample", "--material", file, "--fit", "smooth:E2", "--wo", "0.3,0,-0.9", "-n", "3"});
  ASSERT_EQ(below.status, 0) << below.err;
  EXPECT_EQ(below.out, "0,0,0,0,0,0,0\n0,0,0,0,0,0,0\n0,0,0,0,0,0,0\n") << "no valid sample for a viewer below the surface";
  expectOneLineError(runGlossy({"sample", "--material", file, "--fit", "smooth:E2", "--wo", "0,0,0", "-n", "3"}), "--wo");
  expectOneLineError(runGlossy({"sample", "--material", file, "--fit", "smooth:E2", "--wo", "1,x", "-n", "3"}), "--wo");
  expectOneLineError(runGlossy({"sample", "--measured", "/nonexistent/t.binary", "--wo", "0,0,1", "-n", "3"}), "t.binary");
  EXPECT_EQ(runGlossy({"sample", "--material", file, "--fit", "smooth:E2", "-n", "3"}).status, 2) << "--wo is required";
}

TEST(Cli, UsageErrorsExitTwo) {
  EXPECT_EQ(runGlossy({}).status, 2);
  EXPECT_EQ(runGlossy({"frobnicate"}).status, 2);
  EXPECT_EQ(runGlossy({"eval"}).status, 2);
  EXPECT_EQ(runGlossy({"eval", "--material", "x.toml"}).status, 2) << "--material needs --fit";
  EXPECT_EQ(runGlossy({"eval", "--measured", "a.binary", "--material", "x.toml", "--fit", "smooth:E2"}).status, 2);
  EXPECT_EQ(runGlossy({"import"}).status, 2);
}

// Every message is one safe line (materials/core/text.h, safeLine, applied where InputError is formed):
// escape sequences, line breaks, NUL and bidirectional overrides from arguments, globs, panel names and
// file contents are shown escaped, and a long echo is cut with its length.
TEST(Cli, MessagesAreOneSafeLine) {
  TempDir tmp;
  const std::string esc = "\x1b[2J\x1b]0;owned\x07";
  const auto expectSafe = [](const RunResult& r, const std::string& mention) {
    expectOneLineError(r, mention);
    EXPECT_EQ(r.err.find("\xe2\x80\xae"), std::string::npos) << "a bidirectional override passed: " << r.err;
    EXPECT_LT(r.err.size(), 1200u) << r.err;
  };
  // Arguments: a file name, a panel list, an unknown option (CLI11's own message).
  RunResult r = runGlossy({"render", "--scene", (tmp / (esc + "\nglossy: all good\n.gltf")).string(), "-o", (tmp / "x.exr").string()});
  expectSafe(r, "\\x1b[2J");
  expectSafe(r, "\\nglossy: all good\\n.gltf");
  r = runGlossy({"sheet", "--material", (materialsDir() / "chrome.toml").string(), "--panels", "measured," + esc + "\xe2\x80\xae:E2",
                 "-o", (tmp / "s.exr").string()});
  expectSafe(r, "\\x1b]0;owned\\x07");
  expectSafe(r, "\\u202e");
  r = runGlossy({"render", "--bogus" + esc});
  expectSafe(r, "\\x1b");
  // A glob of a study file, and a long one: cut, with its length.
  writeText(tmp / "study.toml", "materials = [\"merl/\\u001b[31m\\u0000red*\"]\n[lightings]\nsky = { sky = true }\n");
  r = runGlossy({"study", (tmp / "study.toml").string(), "-o", (tmp / "out").string()});
  expectSafe(r, "\\x1b[31m\\x00red*");
  writeText(tmp / "study.toml", "materials = [\"merl/" + std::string(5000, 'a') + "*\"]\n[lightings]\nsky = { sky = true }\n");
  r = runGlossy({"study", (tmp / "study.toml").string(), "-o", (tmp / "out").string()});
  expectSafe(r, "(5,006 characters)");
  // A file's content: a material's name with a NUL, an escape and a line break in it.
  writeText(tmp / "m.toml", "name = \"evil\\u0000\\u001b[1A\\nx\"\n");
  expectSafe(runGlossy({"eval", "--material", (tmp / "m.toml").string(), "--fit", "smooth:E2"}),
             "m.toml");
}

TEST(Cli, EverySubcommandHasHelp) {
  for (const char* sub : {"eval", "import", "list", "render", "sample"}) {
    const RunResult r = runGlossy({sub, "--help"});
    EXPECT_EQ(r.status, 0) << sub;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << sub;
  }
  EXPECT_EQ(runGlossy({"--help"}).status, 0);
}

TEST(CliImport, RegeneratesTheCommittedLibraryByteForByte) {
  GLOSSY_REQUIRE_SHARED("fits");
  GLOSSY_REQUIRE_SHARED("seed/supplement.txt");
  TempDir out;
  // Over copies of the committed files, as scripts/generate-materials does: the published fits are rewritten
  // from the sources, glossy's own fits beside them (by = "glossy") are kept as they are.
  for (const auto& e : std::filesystem::directory_iterator(materialsDir()))
    if (e.path().extension() == ".toml") std::filesystem::copy_file(e.path(), out / e.path().filename().string());
  std::vector<std::string> args = {"import"};
  for (const auto& e : std::filesystem::directory_iterator(sharedDir() / "fits"))
    if (e.path().extension() == ".fit") args.push_back(e.path().string());
  args.push_back((sharedDir() / "seed/supplement.txt").string());
  // Ngan et al. 2005's fits, committed beside the library (materials/published-fits/SOURCES.md).
  for (const auto& e : std::filesystem::directory_iterator(sourceDir() / "materials/published-fits"))
    if (e.path().extension() == ".fit") args.push_back(e.path().string());
  args.insert(args.end(), {"-o", out.path().string()});
  const RunResult r = runGlossy(args);
  ASSERT_EQ(r.status, 0) << r.err;
  size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(out.path())) {
    const auto committed = materialsDir() / e.path().filename();
    ASSERT_TRUE(std::filesystem::exists(committed)) << e.path().filename() << " is not committed";
    EXPECT_EQ(readText(e.path()), readText(committed)) << e.path().filename() << " differs: run scripts/generate-materials";
    ++files;
  }
  EXPECT_EQ(files, 100u);
}

TEST(CliImport, AMalformedExistingFileStopsTheImportBeforeAnythingIsWritten) {
  GLOSSY_REQUIRE_SHARED("seed/supplement.txt");
  TempDir out;
  writeText(out / "chrome.toml", "name = \"chrome\"\n[[fit]]\nmodel = 3\n");
  const RunResult r = runGlossy({"import", (sharedDir() / "seed/supplement.txt").string(), "-o", out.path().string()});
  expectOneLineError(r, "chrome.toml");
  EXPECT_FALSE(std::filesystem::exists(out / "alum-bronze.toml"));
  const RunResult ok = runGlossy({"import", (sharedDir() / "seed/supplement.txt").string(), "-o", out.path().string(), "--replace"});
  EXPECT_EQ(ok.status, 0) << ok.err;
  EXPECT_TRUE(std::filesystem::exists(out / "alum-bronze.toml"));
  for (const auto& e : std::filesystem::directory_iterator(out.path()))
    EXPECT_EQ(e.path().string().find(".tmp."), std::string::npos) << "temporary left behind: " << e.path();
}

TEST(CliList, ListsTheLibrary) {
  const RunResult r = runGlossy({"list", materialsDir().string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("100 materials, 600 of the grid's fits"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("alum-bronze"), std::string::npos);
  // The fits no column shows are listed too, by id: a model outside the grid, and glossy's refits.
  const size_t at = r.out.find("\nalum-bronze ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::string line = r.out.substr(at + 1, r.out.find('\n', at + 1) - at - 1);
  for (const char* other : {"ggx:E2:glossy 0.", "cook-torrance:E2:glossy 0.", "microfacet:E2:glossy 0."})
    EXPECT_NE(line.find(other), std::string::npos) << other << " missing from: " << line;
  EXPECT_EQ(r.out.find(" 0 other fits"), std::string::npos) << r.out;
}

// Fits outside the grid, e.g. Ngan et al.'s published ones, as columns of their own.
TEST(CliList, ListsTheFitsPanelsNames) {
  const RunResult r = runGlossy({"list", "--panels", "measured,ward:Ngan05", materialsDir().string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("Ward Ngan05"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("100 materials, 86 of the named fits"), std::string::npos) << r.out;
  expectOneLineError(runGlossy({"list", "--panels", "ward:E7", materialsDir().string()}), "--panels");
}

// A grid's name stands for its panels wherever panels are named; every fit of a named grid has a colour of
// its own (not the grey of a fit the table lacks); an unknown word is refused naming the grids.
TEST(CliList, NamedGridsAreTheirPanelsEachInItsOwnColour) {
  const RunResult people = runGlossy({"list", "--panels", "lavoue2021", materialsDir().string()});
  ASSERT_EQ(people.status, 0) << people.err;
  for (const char* column : {"Microfacet E2", "Smooth E2", "Ward Ngan05", "BP Ngan05", "Lafortune Ngan05", "SGD Bagher12"})
    EXPECT_NE(people.out.find(column), std::string::npos) << column << ": " << people.out;
  // 100 materials × ABC's two + Bagher's 100 + 86 each of Ngan's three.
  EXPECT_NE(people.out.find("100 materials, " + std::to_string(200 + 100 + 3 * 86) + " of the named fits"), std::string::npos) << people.out;
  const RunResult supplement = runGlossy({"list", "--panels", "supplement", materialsDir().string()});
  const RunResult byDefault = runGlossy({"list", materialsDir().string()});
  ASSERT_EQ(supplement.status, 0) << supplement.err;
  // The same table (its last line says "named" for a --panels list where the default says "the grid's").
  const auto table = [](const std::string& out) { return out.substr(out.find("\n\n"), out.rfind("\n\n") - out.find("\n\n")); };
  EXPECT_TRUE(table(supplement.out) == table(byDefault.out));
  for (const NamedGrid& g : namedGrids()) {
    std::set<std::string> colours;
    for (const SheetPanel& p : parsePanels(g.name, "--panels")) {
      EXPECT_NE(p.colour, "#999999") << g.name << ": " << p.fit << " has no colour of its own";
      EXPECT_TRUE(colours.insert(p.colour).second) << g.name << ": " << p.fit << " shares its colour";
    }
  }
  expectOneLineError(runGlossy({"list", "--panels", "people", materialsDir().string()}),
                     "--panels: 'people' is not a grid (supplement, lavoue2021, ngan05)");
}

// `glossy eval` reaches Ngan et al.'s and Bagher et al.'s fits by MODEL:Ngan05 and sgd:Bagher12, with the value the
// model gives in C++.
TEST(CliEval, EvaluatesOtherPapersPublishedFits) {
  const auto file = materialsDir() / "alum-bronze.toml";
  const MaterialFile m = loadMaterialFile(file);
  int evaluated = 0;
  for (const Fit& f : m.fits) {
    if (f.id.isLowMetric()) continue;
    ++evaluated;
    const RunResult r = runGlossy({"eval", "--material", file.string(), "--fit", f.id.str()}, "0.5,0,0.8660254037844386,-0.5,0,0.8660254037844386\n");
    ASSERT_EQ(r.status, 0) << r.err;
    const Rgb want = eval(makeBrdf(f), Vec3(0.5, 0, 0.8660254037844386), Vec3(-0.5, 0, 0.8660254037844386));
    double got[3];
    ASSERT_EQ(std::sscanf(r.out.c_str(), "%lf,%lf,%lf", &got[0], &got[1], &got[2]), 3) << r.out;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-12 * want[c]) << f.id.str();
  }
  EXPECT_EQ(evaluated, 7) << "six of Ngan et al.'s fits and Bagher et al.'s";
}

// With no path, from the checkout: a section per database folder that holds parameter files, headed by its
// networks' label, its folder and its count, in folder order.
TEST(CliList, GroupsTheLibraryByDatabase) {
  const RunResult r = runGlossyIn(sourceDir(), {"GLOSSY_MERL_DIR"}, {"list"});
  ASSERT_EQ(r.status, 0) << r.err;
  size_t last = 0, materials = 0;
  for (const auto& [folder, label] : std::vector<std::pair<std::string, std::string>>{
           {"merl", "MERL (NBRDF reconstruction)"},
           {"nielsen2015", "Nielsen 2015 (NBRDF reconstruction)"},
           {"rgl-epfl", "RGL-EPFL (NBRDF reconstruction)"}}) {
    size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(libraryDir() / folder)) files += e.path().extension() == ".toml";
    const std::string heading =
        label + " — materials/library/" + folder + ", " + std::to_string(files) + (files == 1 ? " material\n" : " materials\n");
    const size_t at = r.out.find(heading);
    if (files == 0) {
      EXPECT_EQ(at, std::string::npos) << heading;
      continue;
    }
    ASSERT_NE(at, std::string::npos) << heading << r.out;
    EXPECT_GT(at, last) << heading;
    last = at;
    materials += files;
  }
  EXPECT_GE(materials, 100u);
  EXPECT_NE(r.out.find("\n" + std::to_string(materials) + " materials, "), std::string::npos) << r.out;
  EXPECT_LT(r.out.find("\nalum-bronze "), r.out.find("\nchrome ")) << "sorted within";
}

// Files given on the command line go under their folders the same way: a folder's heading is its networks'
// label (none without networks), its materials sorted under it.
TEST(CliList, GroupsGivenFilesByTheirFolder) {
  TempDir tmp;
  for (const char* folder : {"a", "b", "c"}) std::filesystem::create_directories(tmp / folder);
  for (const char* file : {"chrome.toml", "chrome.nbrdf", "gold-paint.toml"})
    std::filesystem::copy_file(materialsDir() / file, tmp / "a" / file);
  std::filesystem::copy_file(libraryDir() / "rgl-epfl/spectralon.nbrdf", tmp / "b/spectralon.nbrdf");
  std::string chrome = readText(materialsDir() / "chrome.toml");
  chrome.replace(chrome.find("name = \"chrome\""), 15, "name = \"spectralon\"");
  chrome.replace(chrome.find("measured = \"chrome.binary\""), 26, "measured = \"spectralon.binary\"");
  writeText(tmp / "b/spectralon.toml", chrome);
  std::filesystem::copy_file(materialsDir() / "blue-rubber.toml", tmp / "c/blue-rubber.toml");
  const RunResult r = runGlossyIn(tmp.path(), {"GLOSSY_MERL_DIR"},
                                  {"list", "c/blue-rubber.toml", "b/spectralon.toml", "a/gold-paint.toml", "a/chrome.toml"});
  ASSERT_EQ(r.status, 0) << r.err;
  const size_t a = r.out.find("\nMERL (NBRDF reconstruction) — a, 2 materials\n");
  const size_t b = r.out.find("\nRGL-EPFL (NBRDF reconstruction) — b, 1 material\n");
  const size_t c = r.out.find("\nc, 1 material\n");
  ASSERT_NE(a, std::string::npos) << r.out;
  ASSERT_NE(b, std::string::npos) << r.out;
  ASSERT_NE(c, std::string::npos) << r.out;
  const size_t chromeRow = r.out.find("\nchrome "), goldRow = r.out.find("\ngold-paint "),
               spectralonRow = r.out.find("\nspectralon "), rubberRow = r.out.find("\nblue-rubber ");
  EXPECT_TRUE(a < chromeRow && chromeRow < goldRow && goldRow < b) << r.out;
  EXPECT_TRUE(b < spectralonRow && spectralonRow < c && c < rubberRow) << r.out;
  EXPECT_NE(r.out.find("4 materials, 24 of the grid's fits"), std::string::npos) << r.out;
}

}  // namespace glossy::test
