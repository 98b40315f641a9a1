// glossy merge (renderer/cli/merge_command.cpp): the fits of a job array's shards into parameter files, the
// figures of its sheets into one table, and bad input refused before anything is written.
#include "materials/params/material_file.h"
#include "renderer/sheet/sheet_record.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sstream>

using namespace glossy;
using namespace glossy::test;

namespace {

// A parameter file holding `fits` of alum-bronze's, under the name `name`; as glossy's own fits (as glossy fit
// --out-dir writes them) when `glossys`.
void writeFits(const std::filesystem::path& path, const std::string& name, const std::vector<std::string>& fits, bool glossys = true) {
  MaterialFile m = loadMaterialFile(materialsDir() / "alum-bronze.toml");
  m.name = name;
  std::vector<Fit> kept;
  for (Fit f : m.fits)
    if (std::find(fits.begin(), fits.end(), f.id.str()) != fits.end()) {
      if (glossys) f.id.by = FitId::kGlossy, f.date = "2026-12-01", f.settings = "grid";
      kept.push_back(f);
    }
  m.fits = kept;
  writeText(path, toToml(m));
}

}  // namespace

TEST(MergeCli, FitsGoIntoTheLibraryBesideThePublishedOnes) {
  TempDir tmp;
  std::filesystem::create_directories(tmp / "shards");
  std::filesystem::create_directories(tmp / "lib");
  writeFits(tmp / "shards/alpha.toml", "alpha", {"cook-torrance:E2", "smooth:E2"});
  writeFits(tmp / "shards/beta.toml", "beta", {"microfacet:E2"});
  writeFits(tmp / "lib/alpha.toml", "alpha", {"cook-torrance:E2", "ashikhmin-shirley:E1"}, false);
  // The library also holds glossy's earlier CT E2, which differs: the shard's replaces it, saying so.
  MaterialFile libAlpha = loadMaterialFile(tmp / "lib/alpha.toml");
  Fit earlier = *libAlpha.findExact({"cook-torrance", "E2"});
  earlier.id.by = FitId::kGlossy, earlier.date = "2026-11-30", earlier.params.set("m", 0.5);
  libAlpha.put(earlier);
  writeText(tmp / "lib/alpha.toml", toToml(libAlpha));
  const MaterialFile published = loadMaterialFile(tmp / "lib/alpha.toml");

  const RunResult r = runGlossy({"merge", "fits", (tmp / "shards").string(), "-o", (tmp / "lib").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("3 fits of 2 materials"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("1 replacing"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("glossy's cook-torrance:E2:glossy fit replaced by " + (tmp / "shards/alpha.toml").string() +
                       "'s of 2026-12-01 (it was of 2026-11-30)"),
            std::string::npos)
      << r.err;
  const MaterialFile alpha = loadMaterialFile(tmp / "lib/alpha.toml");
  const MaterialFile shardAlpha = loadMaterialFile(tmp / "shards/alpha.toml");
  ASSERT_EQ(alpha.fits.size(), 4u);
  EXPECT_TRUE(alpha.findExact({"ashikhmin-shirley", "E1"})) << "a fit of another model is kept";
  EXPECT_EQ(*alpha.findExact({"cook-torrance", "E2"}), *published.findExact({"cook-torrance", "E2"})) << "the paper's fit kept";
  EXPECT_EQ(*alpha.findExact({"cook-torrance", "E2", "glossy"}), *shardAlpha.findExact({"cook-torrance", "E2", "glossy"}));
  EXPECT_EQ(loadMaterialFile(tmp / "lib/beta.toml").fits.size(), 1u) << "a new material's file is made";
}

// A file's published fit where the library has a different one: refused, the library as it was; with
// --replace, replaced, saying so.
TEST(MergeCli, APublishedFitIsNeverReplacedUnasked) {
  TempDir tmp;
  std::filesystem::create_directories(tmp / "shards");
  std::filesystem::create_directories(tmp / "lib");
  writeFits(tmp / "lib/alpha.toml", "alpha", {"cook-torrance:E2"}, false);
  const std::string library = readText(tmp / "lib/alpha.toml");
  MaterialFile other = parseMaterialToml(library, "alpha.toml");
  other.fits[0].params.set("m", 0.5);
  writeText(tmp / "shards/alpha.toml", toToml(other));
  const std::vector<std::string> merge = {"merge", "fits", (tmp / "shards").string(), "-o", (tmp / "lib").string()};
  const RunResult refused = runGlossy(merge);
  expectOneLineError(refused, "published cook-torrance:E2 fit differs from the one in " + (tmp / "shards/alpha.toml").string());
  EXPECT_NE(refused.err.find("--replace"), std::string::npos) << refused.err;
  EXPECT_EQ(readText(tmp / "lib/alpha.toml"), library);

  // The same published fit again is no change.
  writeText(tmp / "shards/alpha.toml", library);
  ASSERT_EQ(runGlossy(merge).status, 0);
  EXPECT_EQ(readText(tmp / "lib/alpha.toml"), library);

  writeText(tmp / "shards/alpha.toml", toToml(other));
  const RunResult replaced = runGlossy([&] { auto a = merge; a.push_back("--replace"); return a; }());
  ASSERT_EQ(replaced.status, 0) << replaced.err;
  EXPECT_NE(replaced.err.find("the published cook-torrance:E2 fit replaced by"), std::string::npos) << replaced.err;
  EXPECT_EQ(loadMaterialFile(tmp / "lib/alpha.toml").fits, other.fits);
}

// Two files of the folder naming one material: which should win is not glossy's to guess.
TEST(MergeCli, TwoFilesNamingOneMaterialAreRefused) {
  TempDir tmp;
  std::filesystem::create_directories(tmp / "shards");
  writeFits(tmp / "shards/alpha.toml", "alpha", {"cook-torrance:E2"});
  writeFits(tmp / "shards/alpha-again.toml", "alpha", {"smooth:E2"});
  const RunResult r = runGlossy({"merge", "fits", (tmp / "shards").string(), "-o", (tmp / "lib").string()});
  expectOneLineError(r, "alpha.toml");
  EXPECT_NE(r.err.find("alpha-again.toml"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(tmp / "lib/alpha.toml"));
}

TEST(MergeCli, BadInputChangesNothing) {
  TempDir tmp;
  std::filesystem::create_directories(tmp / "shards");
  writeFits(tmp / "shards/alpha.toml", "alpha", {"cook-torrance:E2"});
  writeText(tmp / "shards/broken.toml", "name = \"broken\"\n[[fit]]\nmodel = \"nope\"\n");
  expectOneLineError(runGlossy({"merge", "fits", (tmp / "shards").string(), "-o", (tmp / "lib").string()}), "broken.toml");
  EXPECT_FALSE(std::filesystem::exists(tmp / "lib/alpha.toml")) << "nothing written before everything was read";
  expectOneLineError(runGlossy({"merge", "fits", (tmp / "none").string(), "-o", (tmp / "lib").string()}), "none");
  expectOneLineError(runGlossy({"merge", "sheets", (tmp / "shards").string()}), "--csv");
  expectOneLineError(runGlossy({"merge", "sheets", (tmp / "shards").string(), "--csv", (tmp / "t.txt").string()}), "--csv");
  expectOneLineError(runGlossy({"merge", "sheets", (tmp / "empty").string(), "--csv", (tmp / "t.csv").string()}), "empty");
}

TEST(MergeCli, SheetsFiguresInOneTable) {
  GLOSSY_REQUIRE_SHARED("merl/alum-bronze.binary.xz");
  TempDir tmp;
  std::filesystem::create_directories(tmp / "lib");
  for (const char* name : {"alum-bronze", "chrome"})
    std::filesystem::copy_file(materialsDir() / (std::string(name) + ".toml"), tmp / "lib" / (std::string(name) + ".toml"));
  RunResult r = runGlossy({"sheets", (tmp / "lib").string(), "-o", (tmp / "sheets").string(), "--merl-dir",
                           (sharedDir() / "merl").string(), "--width", "16", "--height", "16", "--spp", "8"});
  ASSERT_EQ(r.status, 0) << r.err;
  r = runGlossy({"merge", "sheets", (tmp / "sheets").string(), "--csv", (tmp / "out/errors.csv").string(), "--json",
                 (tmp / "out/errors.json").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto rows = readCsv(tmp / "out/errors.csv");
  ASSERT_EQ(rows.size(), 16u) << "2 sheets × (7 panels + the noise floor)";
  const SheetRecord chrome = readSheetRecord(tmp / "sheets/chrome.exr");
  size_t checked = 0;
  std::string warning;
  for (const std::string& w : chrome.warnings) warning.append(warning.empty() ? "" : "; ").append(w);
  ASSERT_FALSE(warning.empty()) << "8 spp on 16² panels: noise swamps the figures, the sheet warns";
  ASSERT_TRUE(chrome.noiseFloor);
  for (const auto& row : rows) {
    if (row.at("material") != "chrome") continue;
    EXPECT_EQ(row.at("warning"), warning);
    if (row.at("panel") == "noise_floor") {
      EXPECT_EQ(std::stod(row.at("relative_rmse_noisy")), *chrome.noiseFloor->relativeRmseNoisy);
      EXPECT_EQ(std::stod(row.at("flip")), *chrome.noiseFloor->flip.value);
      EXPECT_EQ(std::stod(row.at("delta_e_itp")), *chrome.noiseFloor->deltaEItp.value);
      EXPECT_EQ(std::stod(row.at("ssim_lo")), *chrome.noiseFloor->ssim.lo);
    }
    if (row.at("panel") == "measured" || row.at("panel") == "noise_floor") continue;
    const PanelRecord* p = chrome.panel(row.at("panel"));
    ASSERT_TRUE(p);
    ASSERT_TRUE(p->relativeRmse.value);
    EXPECT_EQ(std::stod(row.at("relative_rmse")), *p->relativeRmse.value);
    EXPECT_EQ(std::stod(row.at("relative_rmse_lo")), *p->relativeRmse.lo);
    EXPECT_EQ(std::stod(row.at("E2")), *p->e2);
    ++checked;
  }
  EXPECT_EQ(checked, 6u);
  // The verdict, the last column, names several models in a tie: quoted, as CSV quotes a field with commas.
  const std::string verdict = chrome.verdict.find(',') == std::string::npos ? chrome.verdict : "\"" + chrome.verdict + "\"";
  EXPECT_NE(readText(tmp / "out/errors.csv").find(",0," + verdict + ","), std::string::npos) << chrome.verdict;
  const nlohmann::json doc = nlohmann::json::parse(readText(tmp / "out/errors.json"));
  ASSERT_EQ(doc["sheets"].size(), 2u);
  EXPECT_EQ(doc["sheets"][1]["material"], "chrome");
  EXPECT_EQ(doc["sheets"][1]["panels"].size(), 7u);
  EXPECT_EQ(doc["sheets"][1]["verdict"], chrome.verdict);
  EXPECT_EQ(doc["sheets"][1]["warnings"], chrome.warnings);
  EXPECT_EQ(doc["sheets"][1]["noise_floor"]["relative_rmse_noisy"], *chrome.noiseFloor->relativeRmseNoisy);
  EXPECT_TRUE(doc["sheets"][1]["panels"][0]["relative_rmse"].is_null()) << "the measured panel has no error figure";
}

// Sharded fitting: the tables split by cost, each shard's log says which it took and from where.
TEST(FitCli, ShardsSplitTheTablesAndSayFromWhere) {
  GLOSSY_REQUIRE_SHARED("merl/alum-bronze.binary.xz");
  TempDir tmp;
  std::filesystem::create_directories(tmp / "tables");
  for (const char* name : {"alum-bronze", "blue-rubber", "chrome"})
    std::filesystem::create_symlink(sharedDir() / "merl" / (std::string(name) + ".binary.xz"), tmp / "tables" / (std::string(name) + ".binary.xz"));
  std::set<std::string> fitted;
  for (int i = 0; i < 2; ++i) {
    const RunResult r = runGlossy({"fit", "--measured-dir", (tmp / "tables").string(), "--out-dir", (tmp / "out").string(),
                                   "--model", "smooth", "--metric", "E2", "--starts", "1", "--max-iterations", "3", "--shard",
                                   std::to_string(i) + "/2"});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("shard " + std::to_string(i) + "/2 from --shard " + std::to_string(i) + "/2"), std::string::npos) << r.err;
  }
  for (const auto& e : std::filesystem::directory_iterator(tmp / "out")) fitted.insert(e.path().filename().string());
  EXPECT_EQ(fitted, (std::set<std::string>{"alum-bronze.toml", "blue-rubber.toml", "chrome.toml"}));
  expectOneLineError(runGlossy({"fit", "--measured", (tmp / "tables/chrome.binary.xz").string(), "--model", "smooth", "--metric",
                                "E2", "--shard", "0/2"}),
                     "--shard");
}
