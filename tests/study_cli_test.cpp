// glossy study (renderer/cli/study_command.cpp, renderer/app/study_file.h): a tiny study's outputs are the same
// bytes whether it runs whole, in shards then --analyse, or resumed after an interruption; a bad study file
// or destination is refused in one line before any work.
#include "renderer/app/sheet_job.h"
#include "renderer/app/study_file.h"
#include "renderer/study/study_plan.h"
#include "renderer/study/study_rows.h"
#include "support/test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <fstream>
#include <future>
#include <sys/resource.h>
#include <map>
#include <set>
#include <thread>

using namespace glossy;
using namespace glossy::test;

namespace fs = std::filesystem;

namespace {

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const size_t at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// Two materials of two databases × two lightings, 16² panels at 16 spp, four panels: seconds in all.
const std::string kTinyStudy = R"(# a tiny study (docs/study.md)
materials = ["merl/gold-paint", "nielsen2015/bluebook"]

[lightings]
sky = { sky = true }
grey = { constant = [0.8, 0.8, 0.9] }

[scenes]
preview = { builtin = "preview" }

[settings]
width = 16
height = 16
spp = 16
seed = 7
threads = 2
panels = "measured,microfacet:E2,smooth:E2,cook-torrance:E2"

[analysis]
resamples = 200
)";

// Every file under `root` (relative path → bytes), but the sheets' EXRs, which record their render time.
std::map<std::string, std::string> outputs(const fs::path& root) {
  std::map<std::string, std::string> files;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file() && e.path().extension() != ".exr") files[fs::relative(e.path(), root).generic_string()] = readText(e.path());
  return files;
}

void expectSameOutputs(const fs::path& a, const fs::path& b) {
  const auto x = outputs(a), y = outputs(b);
  ASSERT_FALSE(x.empty());
  for (const auto& [file, bytes] : x) {
    const auto it = y.find(file);
    ASSERT_NE(it, y.end()) << file << " is in " << a << " but not in " << b;
    EXPECT_TRUE(it->second == bytes) << file << " differs between " << a << " and " << b;
  }
  EXPECT_EQ(x.size(), y.size());
}

RunResult runStudy(const fs::path& file, const fs::path& out, std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"study", file.string(), "-o", out.string()};
  args.insert(args.end(), more.begin(), more.end());
  return runGlossy(args);
}

}  // namespace

TEST(StudyCli, WholeShardedAndResumedRunsWriteTheSameBytes) {
  TempDir tmp;
  writeText(tmp / "tiny.toml", kTinyStudy);

  const RunResult whole = runStudy(tmp / "tiny.toml", tmp / "whole");
  ASSERT_EQ(whole.status, 0) << whole.err;
  for (const char* step : {"analysis 1/6: ", "analysis 6/6: "}) EXPECT_NE(whole.err.find(step), std::string::npos) << whole.err;
  for (const char* s : {"sky/gold-paint", "sky/bluebook", "grey/gold-paint", "grey/bluebook"})
    for (const char* ext : {".exr", ".png"})
      EXPECT_TRUE(fs::is_regular_file(tmp / "whole/sheets/preview" / (std::string(s) + ext))) << s << ext;
  ASSERT_TRUE(fs::is_directory(tmp / "whole/analysis"));
  EXPECT_FALSE(fs::is_empty(tmp / "whole/analysis"));
  const std::vector<study::StudyRow> rows = study::readStudyRows(tmp / "whole");
  ASSERT_EQ(rows.size(), 2u * 2u * 3u) << "a row per model panel of every sheet";
  EXPECT_EQ(rows.front().material, "bluebook");
  EXPECT_EQ(rows.front().database, "Nielsen 2015");
  EXPECT_EQ(rows.front().fitSource, "glossy") << "Nielsen's files hold glossy's fits only";
  EXPECT_EQ(rows.front().fit, "microfacet:E2:glossy");
  EXPECT_EQ(rows.front().label, "Microfacet E2") << "the model's label, whoever made the fit";
  EXPECT_EQ(rows.front().lighting, "grey");
  EXPECT_EQ(rows.back().material, "gold-paint");
  EXPECT_EQ(rows.back().database, "MERL");
  EXPECT_EQ(rows.back().fitSource, "published");
  EXPECT_EQ(rows.back().fit, "cook-torrance:E2");
  EXPECT_EQ(rows.back().fitMetric, "E2");
  EXPECT_EQ(rows.back().sheet, "sheets/preview/sky/gold-paint.exr");
  EXPECT_EQ(rows.back().width, 16);
  EXPECT_EQ(rows.back().spp, 16);
  EXPECT_EQ(rows.back().seed, 7u);
  EXPECT_TRUE(rows.back().rrmse.has_value());
  // What the results stand on: the study file, kept as it was read, and its inputs in results.json.
  EXPECT_EQ(readText(tmp / "whole/analysis/study.toml"), kTinyStudy);
  {
    const nlohmann::json results = nlohmann::json::parse(readText(tmp / "whole/analysis/results.json"));
    const nlohmann::json& p = results["provenance"];
    EXPECT_EQ(p["studyFile"], "tiny.toml");
    EXPECT_EQ(p["settings"]["spp"], 16);
    EXPECT_EQ(p["settings"]["seed"], 7);
    EXPECT_EQ(p["settings"]["panels"], "measured,microfacet:E2,smooth:E2,cook-torrance:E2");
    ASSERT_EQ(p["lightings"].size(), 2u);
    EXPECT_EQ(p["lightings"][0]["name"], "grey");
    EXPECT_EQ(p["lightings"][0]["kind"], "constant");
    EXPECT_EQ(p["lightings"][1]["kind"], "sky");
    EXPECT_EQ(p["scenes"][0]["builtin"], "preview");
    EXPECT_EQ(p["scenes"][0]["digest"].get<std::string>().size(), 16u);
    ASSERT_EQ(p["materials"].size(), 2u);
    EXPECT_EQ(p["materials"][0]["name"], "bluebook");
    EXPECT_EQ(p["materials"][0]["measured"], "NBRDF reconstruction");
    EXPECT_EQ(p["materials"][1]["name"], "gold-paint");
    EXPECT_NE(p["materials"][1]["measured"], "none") << "gold-paint's measured panel was rendered";
    EXPECT_FALSE(results["glossy"]["commit"].get<std::string>().empty());
  }

  // Two shards, then the analysis: a shard renders its share and does not analyse.
  for (const char* shard : {"0/2", "1/2"}) {
    const RunResult r = runStudy(tmp / "tiny.toml", tmp / "sharded", {"--shard", shard});
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_FALSE(fs::exists(tmp / "sharded/analysis")) << "a shard analyses nothing";
  }
  const RunResult analysed = runStudy(tmp / "tiny.toml", tmp / "sharded", {"--analyse"});
  ASSERT_EQ(analysed.status, 0) << analysed.err;
  EXPECT_TRUE(whole.out.ends_with(analysed.out)) << "the same summary after the sheets' tables:\n" << analysed.out;
  expectSameOutputs(tmp / "whole", tmp / "sharded");

  // Interrupted: one shard of three done, one sheet of it cut short; the whole run keeps the rest.
  ASSERT_EQ(runStudy(tmp / "tiny.toml", tmp / "resumed", {"--shard", "0/3"}).status, 0);
  std::vector<fs::path> done;
  for (const auto& e : fs::recursive_directory_iterator(tmp / "resumed/sheets"))
    if (e.path().extension() == ".exr") done.push_back(e.path());
  ASSERT_FALSE(done.empty());
  fs::resize_file(done.front(), fs::file_size(done.front()) / 2);
  const RunResult resumed = runStudy(tmp / "tiny.toml", tmp / "resumed");
  ASSERT_EQ(resumed.status, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("rendering it again"), std::string::npos) << resumed.err;
  if (done.size() > 1) {
    EXPECT_NE(resumed.err.find("complete, skipped"), std::string::npos) << resumed.err;
  }
  EXPECT_TRUE(resumed.out.ends_with(analysed.out)) << resumed.out;
  expectSameOutputs(tmp / "whole", tmp / "resumed");

  // --analyse with a sheet missing: said, not analysed.
  fs::remove(tmp / "sharded/sheets/preview/grey/bluebook.exr");
  const RunResult incomplete = runStudy(tmp / "tiny.toml", tmp / "sharded", {"--analyse"});
  EXPECT_EQ(incomplete.status, 1);
  EXPECT_NE(incomplete.err.find("1 of 4 sheets are not complete"), std::string::npos) << incomplete.err;
}

// Each bad study file fails in one line naming the file and the key, before any folder is made.
// A study file that sets no cost renders each sheet to kStudyTargetError (at most kTargetErrorSppCap spp);
// settings.spp or time is a fixed cost, as given; a target-error of its own wins.
TEST(StudyCli, ASheetsPrecisionIsATargetUnlessTheFileSetsACost) {
  TempDir tmp;
  const auto load = [&](const std::string& settings) {
    writeText(tmp / "s.toml", "materials = [\"merl/gold-paint\"]\n[lightings]\nsky = { sky = true }\n" + settings);
    return app::loadStudyFile(tmp / "s.toml", libraryDir()).job.settings;
  };
  const SheetSettings none = load("");
  EXPECT_EQ(none.targetError, app::kStudyTargetError);
  EXPECT_EQ(none.spp, app::kTargetErrorSppCap);
  EXPECT_EQ(load("[settings]\nwidth = 32\n").targetError, app::kStudyTargetError);
  const SheetSettings fixed = load("[settings]\nspp = 16\n");
  EXPECT_EQ(fixed.targetError, 0.0);
  EXPECT_EQ(fixed.spp, 16);
  EXPECT_EQ(load("[settings]\ntime = 2\n").targetError, 0.0);
  const SheetSettings own = load("[settings]\ntarget-error = 0.1\nspp = 256\n");
  EXPECT_EQ(own.targetError, 0.1);
  EXPECT_EQ(own.spp, 256);
}

TEST(StudyCli, BadStudyFilesAreRefusedBeforeAnyWork) {
  TempDir tmp;
  const std::string head = "materials = \"merl/gold-paint\"\n";
  const std::string sky = "[lightings]\nsky = { sky = true }\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {head + "colour = 1\n" + sky, "colour: unknown key"},
      {head + sky + "[settings]\nsamples = 4\n", "settings.samples: unknown key"},
      {head + sky + "[settings]\nspp = nan\n", "settings.spp: must be a whole number"},
      {head + sky + "[settings]\nspp = inf\n", "settings.spp: must be a whole number"},
      {head + sky + "[settings]\nwidth = 0\n", "settings.width: must be a whole number in [8, 16384]"},
      {head + sky + "[settings]\nwidth = 16384\nheight = 16384\n", "--width"},
      {head + sky + "[settings]\ntarget-error = -1.0\n", "settings.target-error"},
      {head + sky + "[settings]\npanels = \"measured,nonsense:E2\"\n", "settings.panels"},
      {"materials = \"merl/no-such-*\"\n" + sky, "'merl/no-such-*' matches no material"},
      {"materials = [\"../merl/*\"]\n" + sky, "is not a glob over the library"},
      {"materials = [\"merl/[ab\"]\n" + sky, "is not a glob over the library"},
      {head, "lightings: give at least one"},
      {head + "[lightings]\nstudio = { env = \"no-such.hdr\" }\n", "lightings.studio.env: no such file"},
      {head + "[lightings]\n\"../up\" = { sky = true }\n", "is not a plain name"},
      {head + "[lightings]\ngrey = { constant = -1.0 }\n", "lightings.grey.constant: radiance must be"},
      {head + "[lightings]\ngrey = { constant = [1.0, inf, 1.0] }\n", "lightings.grey.constant: radiance must be"},
      {head + "[lightings]\nboth = { sky = true, constant = 1.0 }\n", "lightings.both: give exactly one"},
      {head + "[lightings]\nsky = { sky = true, rotate = 400 }\n", "lightings.sky.rotate: must be a finite number in [-360, 360]"},
      {head + sky + "[scenes]\nbox = { builtin = \"box\" }\n", "scenes.box.builtin: 'box' is not a built-in scene"},
      {head + sky + "[scenes]\nmine = { gltf = \"missing.gltf\" }\n", "scenes.mine.gltf: no such file"},
      {head + "perceptual = \"no-such-folder\"\n" + sky, "perceptual: no such folder"},
      {head + sky + "[analysis]\nreference = \"Nobody E9\"\n", "analysis.reference"},
      {"materials = 3\n" + sky, "materials: must be a glob"},
      {"materials = [\n", "TOML syntax error"},
      // What the analysis would refuse once every sheet had rendered is refused before the first.
      {head + sky + "[settings]\npanels = \"measured,microfacet:E2,microfacet:E2:glossy\"\n", "settings.panels: 'microfacet:E2' and "
                                                                                              "'microfacet:E2:glossy' are two fits of one model"},
      {head + sky + "[settings]\npanels = \"measured\"\n", "settings.panels: 'measured' has no model panel"},
      {head + sky + "[settings]\npanels = \"microfacet:E2,smooth:E2\"\n", "has no measured panel"},
      {"materials = \"nielsen2015/bluebook\"\n" + sky + "[settings]\npanels = \"measured,ggx:E2\"\n", "materials: no material chosen has a fit"},
      {head + "perceptual = \"perceptual\"\n" + sky, "PerceptualDistances.csv:2: "},
  };
  // Perceptual tables that do not parse.
  fs::create_directories(tmp / "perceptual");
  writeText(tmp / "perceptual/PerceptualDistances.csv", "\"METHOD\";\"BRDF\";\"DISTANCE\"\n\"ABC\";\"gold-paint\";not-a-number\n");
  writeText(tmp / "perceptual/MaterialType.csv", "BRDF;Type\ngold-paint;Metal\n");
  for (const auto& [text, mention] : cases) {
    SCOPED_TRACE(text);
    writeText(tmp / "bad.toml", text);
    const RunResult r = runStudy(tmp / "bad.toml", tmp / "out");
    expectOneLineError(r, "bad.toml");
    expectOneLineError(r, mention);
    EXPECT_FALSE(fs::exists(tmp / "out")) << "nothing is made for a bad study";
  }
  // A folder of someone else's files is not a study's output.
  writeText(tmp / "good.toml", head + sky);
  fs::create_directories(tmp / "theirs");
  writeText(tmp / "theirs/notes.txt", "mine");
  expectOneLineError(runStudy(tmp / "good.toml", tmp / "theirs"), "not a study's output");
  expectOneLineError(runStudy(tmp / "good.toml", tmp / "out", {"--shard", "0/2", "--analyse"}), "--analyse");
}

// An output folder is a study's own only when glossy says so (renderer/study/study_folder.h): a folder whose
// study.json glossy did not write, or that another study's run claimed, is refused before any work and left
// as it was.
TEST(StudyCli, AFolderIsAStudysOwnOnlyWhenGlossySaysSo) {
  TempDir tmp;
  writeText(tmp / "tiny.toml", kTinyStudy);
  // A user's folder that merely holds a file of that name.
  const std::string notes = "{\"my\": \"notes\"}\n";
  fs::create_directories(tmp / "theirs");
  writeText(tmp / "theirs/study.json", notes);
  expectOneLineError(runStudy(tmp / "tiny.toml", tmp / "theirs"), "-o " + (tmp / "theirs").string() + ": its study.json is not a plan glossy wrote");
  EXPECT_EQ(readText(tmp / "theirs/study.json"), notes);
  EXPECT_FALSE(fs::exists(tmp / "theirs/sheets")) << "no sheet written among the user's files";

  // Another study's folder, at other settings: neither re-rendered nor re-analysed.
  ASSERT_EQ(runStudy(tmp / "tiny.toml", tmp / "out").status, 0);
  const auto before = outputs(tmp / "out");
  writeText(tmp / "other.toml", replaced(kTinyStudy, "spp = 16", "spp = 8"));
  expectOneLineError(runStudy(tmp / "other.toml", tmp / "out"), "-o " + (tmp / "out").string() + ": holds the output of another study");
  EXPECT_TRUE(outputs(tmp / "out") == before) << "the other study's folder is left as it was";

  // The same study file, edited, is the same study: run again, it does what is left.
  writeText(tmp / "tiny.toml", replaced(kTinyStudy, "resamples = 200", "resamples = 300"));
  const RunResult edited = runStudy(tmp / "tiny.toml", tmp / "out");
  EXPECT_EQ(edited.status, 0) << edited.err;
}

// Two runs of different studies started on one folder: the second is refused, and the first analyses the plan
// it rendered (held in memory), not the one the second would have put in the folder.
TEST(StudyCli, TwoStudiesStartedOnOneFolderDoNotShareIt) {
  TempDir tmp;
  writeText(tmp / "a.toml", kTinyStudy);
  writeText(tmp / "b.toml", replaced(kTinyStudy, R"(materials = ["merl/gold-paint", "nielsen2015/bluebook"])", R"(materials = ["merl/chrome"])"));
  auto first = std::async(std::launch::async, [&] { return runStudy(tmp / "a.toml", tmp / "out"); });
  for (int i = 0; i < 1200 && !fs::exists(tmp / "out/study.json"); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(25));
  const RunResult second = runStudy(tmp / "b.toml", tmp / "out");
  const RunResult a = first.get();
  ASSERT_EQ(a.status, 0) << a.err;
  expectOneLineError(second, "holds the output of another study");
  EXPECT_FALSE(fs::exists(tmp / "out/sheets/preview/sky/chrome.exr")) << "the second study rendered nothing there";
  std::set<std::string> materials;
  for (const auto& row : readCsv(tmp / "out/analysis/rows.csv")) materials.insert(row.at("material"));
  EXPECT_EQ(materials, (std::set<std::string>{"bluebook", "gold-paint"})) << "the first study's rows, and only them";
}

// No command writes through a symlink leading out of its output folder (renderer/output/inside_folder.h):
// OUT/analysis or OUT/sheets/SCENE/LIGHTING made a link elsewhere is refused, and nothing is written there.
TEST(StudyCli, NothingIsWrittenThroughASymlinkOutOfTheFolder) {
  TempDir tmp;
  writeText(tmp / "tiny.toml", kTinyStudy);
  ASSERT_EQ(runStudy(tmp / "tiny.toml", tmp / "out").status, 0);
  fs::create_directories(tmp / "elsewhere");
  for (const char* link : {"analysis", "sheets/preview/sky"}) {
    SCOPED_TRACE(link);
    fs::rename(tmp / "out" / link, tmp / "moved");
    fs::create_directory_symlink(tmp / "elsewhere", tmp / "out" / link);
    expectOneLineError(runStudy(tmp / "tiny.toml", tmp / "out"), std::string(link) + " is a symlink leading out of it");
    EXPECT_TRUE(fs::is_empty(tmp / "elsewhere")) << "nothing written outside OUT";
    fs::remove(tmp / "out" / link);
    fs::rename(tmp / "moved", tmp / "out" / link);
  }
  // glossy sheets likewise: a sheet's place a link out of -o.
  fs::create_directories(tmp / "sheets");
  writeText(tmp / "elsewhere/notes.exr", "mine");
  fs::create_symlink(tmp / "elsewhere/notes.exr", tmp / "sheets/chrome.exr");
  expectOneLineError(runGlossy({"sheets", (materialsDir() / "chrome.toml").string(), "--width", "8", "--height", "8", "--spp", "1", "-o",
                                (tmp / "sheets").string()}),
                     "chrome.exr is a symlink leading out of it");
  EXPECT_EQ(readText(tmp / "elsewhere/notes.exr"), "mine");
}

// An analysis is written whole (renderer/util/fresh_folder.h): a rerun leaves no file of an earlier run's
// analysis behind — a perceptual.svg from a run with perceptual data, here planted — and no fresh folder.
TEST(StudyCli, AnAnalysisIsWrittenWhole) {
  TempDir tmp;
  writeText(tmp / "tiny.toml", kTinyStudy);
  ASSERT_EQ(runStudy(tmp / "tiny.toml", tmp / "out").status, 0);
  const auto first = outputs(tmp / "out/analysis");
  writeText(tmp / "out/analysis/perceptual.svg", "<svg/>");
  const RunResult again = runStudy(tmp / "tiny.toml", tmp / "out");
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_FALSE(fs::exists(tmp / "out/analysis/perceptual.svg")) << "an earlier run's figure left beside this run's";
  EXPECT_TRUE(outputs(tmp / "out/analysis") == first);
  for (const auto& e : fs::directory_iterator(tmp / "out"))
    EXPECT_EQ(e.path().filename().string().find(".tmp.glossy-"), std::string::npos) << e.path();
}

// A study's cost is bounded before it starts: a scene and an environment are built when a sheet needs
// them, not one per scene × lighting up front (40 lightings took 1.2 GB before the first sheet, in every
// array task); a study of more sheets than one can hold is refused; the analysis says what it will cost
// before the sheets, and its progress while it runs.
TEST(StudyCli, ACostIsBoundedAndSaidBeforeTheWork) {
  TempDir tmp;
  std::string many = "materials = \"merl/gold-paint\"\n[lightings]\n";
  for (int k = 0; k < 40; ++k) many += "sky" + std::to_string(k) + " = { sky = true, rotate = " + std::to_string(k) + " }\n";
  writeText(tmp / "many.toml", many + "[analysis]\nresamples = 1000000\n");
  rusage before{};
  getrusage(RUSAGE_CHILDREN, &before);
  // --analyse renders nothing: what it holds is what the up-front checks hold.
  const RunResult r = runStudy(tmp / "many.toml", tmp / "out", {"--analyse"});
  rusage after{};
  getrusage(RUSAGE_CHILDREN, &after);
  EXPECT_EQ(r.status, 1) << r.err;
  EXPECT_NE(r.err.find("40 of 40 sheets are not complete"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the analysis will take about"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("analysis.resamples = 1000000"), std::string::npos) << r.err;
  // ru_maxrss (KiB) is the largest of every child so far: only a run larger than those before it shows.
  // One stage at a time: about 160 MiB here; a stage per lighting: 1.2 GB. AddressSanitizer's shadow memory and
  // quarantine hold about three times as much (601 MiB measured under scripts/test --sanitize).
#if defined(__SANITIZE_ADDRESS__)
  constexpr long kBoundKiB = 1800L << 10;
#else
  constexpr long kBoundKiB = 600 << 10;
#endif
  if (before.ru_maxrss < kBoundKiB) {
    EXPECT_LT(after.ru_maxrss, kBoundKiB) << "the up-front checks of 40 lightings held " << after.ru_maxrss / 1024 << " MiB";
  }

  std::string huge = "materials = \"merl/*\"\n[lightings]\n";
  for (int k = 0; k < 10001; ++k) huge += "grey" + std::to_string(k) + " = { constant = 0.5 }\n";
  writeText(tmp / "huge.toml", huge);
  expectOneLineError(runStudy(tmp / "huge.toml", tmp / "huge"), "sheets, more than a study holds");
  EXPECT_FALSE(fs::exists(tmp / "huge"));
}
