// glossy report (renderer/report/): the site it writes from a folder of sheets — every page's images and
// links resolve inside the site, the panel images match the sheet's own PNG, the figures are the EXR's,
// strings from files are escaped, the per-model summary counts right — and the bad input it refuses before
// writing anything. The same site in a real browser: tests/report/browser_test.py (CTest Report.Browser).
#include "renderer/image/exr_image.h"
#include "renderer/report/html_text.h"
#include "renderer/report/model_summary.h"
#include "renderer/sheet/sheet_record.h"
#include "tests/support/test_support.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <regex>
#include <set>
#include <sys/stat.h>
#include <tuple>

namespace glossy::test {

namespace fs = std::filesystem;

namespace {

// Two tiny sheets, rendered once for the suite.
const fs::path& sheetsDir() {
  static TempDir tmp;
  static const fs::path dir = [] {
    std::vector<std::string> args{"sheets", (materialsDir() / "alum-bronze.toml").string(), (materialsDir() / "chrome.toml").string(),
                                  "--width", "32", "--height", "32", "--spp", "8", "--seed", "1", "-o", (tmp / "sheets").string()};
    if (fs::is_directory(sharedDir() / "merl")) args.insert(args.end(), {"--merl-dir", (sharedDir() / "merl").string()});
    const RunResult r = runGlossy(args);
    if (r.status != 0) throw std::runtime_error("glossy sheets failed: " + r.err);
    return tmp / "sheets";
  }();
  return dir;
}

void copySheets(const fs::path& to) {
  fs::create_directories(to);
  for (const auto& e : fs::directory_iterator(sheetsDir())) fs::copy_file(e.path(), to / e.path().filename());
}

RunResult report(const fs::path& sheets, const fs::path& site, const std::string& plots = "") {
  std::vector<std::string> args{"report", sheets.string()};
  if (!plots.empty()) args.push_back(plots);
  args.insert(args.end(), {"-o", site.string()});
  return runGlossy(args);
}

std::vector<fs::path> pages(const fs::path& site) {
  std::vector<fs::path> out;
  for (const auto& e : fs::recursive_directory_iterator(site))
    if (e.path().extension() == ".html") out.push_back(e.path());
  return out;
}


}  // namespace

TEST(ReportCli, EveryImageAndLinkOfEveryPageIsInTheSite) {
  TempDir tmp;
  const RunResult r = report(sheetsDir(), tmp / "site");
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path site = tmp / "site";
  ASSERT_TRUE(fs::is_regular_file(site / "index.html"));
  EXPECT_TRUE(fs::is_regular_file(site / "assets/style.css"));
  EXPECT_TRUE(fs::is_regular_file(site / "assets/report.js"));
  const std::vector<fs::path> all = pages(site);
  EXPECT_EQ(all.size(), 3u);  // the index and two materials
  std::set<fs::path> images;
  for (const fs::path& page : all) {
    const std::string html = readText(page);
    EXPECT_EQ(html.find("http://"), std::string::npos) << page;  // nothing from the network
    EXPECT_EQ(html.find("https://"), std::string::npos) << page;
    for (const std::string& ref : htmlReferences(html)) {
      if (ref.starts_with("data:")) continue;
      EXPECT_EQ(ref.find(".."), ref.starts_with("../../") ? 0u : std::string::npos) << page << ": " << ref;
      const fs::path target = (page.parent_path() / ref).lexically_normal();
      EXPECT_TRUE(fs::is_regular_file(target)) << page << " refers to " << ref << ", which is not in the site";
      EXPECT_TRUE(target.string().starts_with(site.string())) << ref;
      if (ref.ends_with(".png")) images.insert(target);
    }
  }
  // Per material: its seven panels and the sheet below them (the index's thumbnails are measured panels).
  EXPECT_EQ(images.size(), 2u * 8u);
  EXPECT_FALSE(fs::exists(site / "materials/chrome/sheet.png")) << "the sheet is its panels and the part below, each pixel once";
  const std::string index = readText(site / "index.html");
  for (const char* name : {"alum-bronze", "chrome"}) {
    EXPECT_NE(index.find("href=\"materials/" + std::string(name) + "/index.html\""), std::string::npos) << name;
    const RgbImage panel = readRgbImage(site / "materials" / name / "panel-measured.png");
    EXPECT_EQ(panel.width, 32);
    EXPECT_EQ(panel.height, 32);
  }
}

TEST(ReportCli, PanelImagesAreTheSheetPngsPanels) {
  TempDir tmp;
  ASSERT_EQ(report(sheetsDir(), tmp / "site").status, 0);
  const SheetRecord sheet = readSheetRecord(sheetsDir() / "chrome.exr");
  const RgbImage png = readRgbImage(sheetsDir() / "chrome.png");
  for (const PanelRecord& p : sheet.panels) {
    const RgbImage panel = readRgbImage(tmp / "site/materials/chrome" / ("panel-" + p.layer + ".png"));
    ASSERT_EQ(panel.width, p.width);
    double worst = 0.0;
    for (int y = 0; y < p.height; ++y)
      for (int x = 0; x < p.width; ++x)
        for (int c = 0; c < 3; ++c) worst = std::max(worst, double(std::abs(panel.at(x, y)[c] - png.at(p.x + x, p.y + y)[c])));
    EXPECT_LE(worst, 1.0 / 255.0 + 1e-6) << p.layer << ": differs from the sheet's PNG";
  }
}

TEST(ReportCli, TheIndexShowsTheSheetsFigures) {
  TempDir tmp;
  ASSERT_EQ(report(sheetsDir(), tmp / "site").status, 0);
  const std::string index = readText(tmp / "site/index.html");
  const SheetRecord sheet = readSheetRecord(sheetsDir() / "alum-bronze.exr");
  const PanelRecord* ct = sheet.panel("cook_torrance_E2");
  ASSERT_TRUE(ct && ct->relativeRmse.value && ct->e2);
  const std::string value = readImageAttribute(sheetsDir() / "alum-bronze.exr", "glossy:error.cook_torrance_E2.relativeRmse");
  EXPECT_NEAR(*ct->relativeRmse.value, std::stod(value), 1e-5 * std::abs(std::stod(value)));  // the text has 6 digits
  EXPECT_NE(index.find("data-value=\"" + report::sortValue(ct->relativeRmse.value) + "\""), std::string::npos);
  EXPECT_NE(index.find("data-value=\"" + report::sortValue(ct->e2) + "\""), std::string::npos);
  EXPECT_NE(index.find(report::escapeHtml(sheet.verdict)), std::string::npos);
  // Where the measured data came from, without the files' paths: a reconstruction says so on the index too.
  EXPECT_NE(index.find("Measured data: MERL (NBRDF reconstruction) (2 materials)."), std::string::npos);
  const std::string page = readText(tmp / "site/materials/alum-bronze/index.html");
  EXPECT_NE(page.find(report::shortNumber(ct->relativeRmse.lo)), std::string::npos);  // the interval
  EXPECT_NE(page.find("CT E2"), std::string::npos);
  // The measured data by its file's name: a published site carries no folders of the machine that rendered it.
  EXPECT_NE(page.find("alum-bronze."), std::string::npos);
  for (const std::string& html : {index, page}) EXPECT_EQ(html.find("/alum-bronze."), std::string::npos);
}

TEST(ReportCli, StringsFromFilesAreEscaped) {
  TempDir tmp;
  copySheets(tmp / "sheets");
  const std::string hostile = "<script>alert(\"x\")</script>&'";
  {
    OIIO::ImageBuf buf((tmp / "sheets/chrome.exr").string());
    ASSERT_TRUE(buf.read(0, 0, true));
    buf.specmod().attribute("glossy:materialName", "evil");
    buf.specmod().attribute("glossy:material", hostile);
    buf.specmod().attribute("glossy:panel.measured.note", hostile);
    buf.specmod().attribute("glossy:panel.smooth_E2.params", hostile);
    buf.specmod().attribute("glossy:verdict", "closest: " + hostile);
    ASSERT_TRUE(buf.write((tmp / "sheets/evil.exr").string()));
    fs::copy_file(tmp / "sheets/chrome.png", tmp / "sheets/evil.png");
  }
  fs::create_directories(tmp / "plots/evil");
  fs::copy_file(tmp / "sheets/chrome.png", tmp / "plots/evil/p.png");
  writeText(tmp / "plots/evil/plots.json",
            R"({"material": "evil", "measured": "<img src=x onerror=alert(1)>", "figures": [{"kind": "polar", "title": "<i>t</i>", "caption": "<b>c</b>", "png": "p.png"}]})");
  const RunResult r = report(tmp / "sheets", tmp / "site", (tmp / "plots").string());
  ASSERT_EQ(r.status, 0) << r.err;
  for (const fs::path& page : pages(tmp / "site")) {
    const std::string html = readText(page);
    EXPECT_EQ(html.find("<script>alert"), std::string::npos) << page;
    EXPECT_EQ(html.find("<img src=x"), std::string::npos) << page;
    EXPECT_EQ(html.find("<i>t</i>"), std::string::npos) << page;
    EXPECT_EQ(html.find("<b>c</b>"), std::string::npos) << page;
  }
  const std::string page = readText(tmp / "site/materials/evil/index.html");
  EXPECT_NE(page.find("&lt;script&gt;alert(&quot;x&quot;)&lt;/script&gt;&amp;&#39;"), std::string::npos);
  EXPECT_NE(page.find("&lt;img src=x onerror=alert(1)&gt;"), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(tmp / "site/materials/evil/plots/p.webp"));
}

TEST(ReportCli, PlotsAreCopiedLinkedAndFiltered) {
  TempDir tmp;
  const fs::path plots = tmp / "plots/chrome";
  fs::create_directories(plots);
  for (const char* kind : {"theta_h", "polar"}) {
    fs::copy_file(sheetsDir() / "chrome.png", plots / (std::string(kind) + ".png"));
    writeText(plots / (std::string(kind) + ".svg"), "<svg xmlns=\"http://www.w3.org/2000/svg\"/>");
    writeText(plots / (std::string(kind) + ".csv"), "x,y\n0,1\n");
  }
  writeText(plots / "plots.json", R"({"material": "chrome", "figures": [
      {"kind": "theta_h", "title": "Theta-h slices", "caption": "cap", "png": "theta_h.png", "svg": "theta_h.svg", "csv": "theta_h.csv"},
      {"kind": "polar", "title": "Polar lobes", "caption": "cap", "png": "polar.png", "svg": "polar.svg", "csv": "polar.csv"}]})");
  // --plot-data: every file, linked; the pictures as the site keeps them (plot_picture.h).
  RunResult r = runGlossy({"report", sheetsDir().string(), (tmp / "plots").string(), "--plot-data", "-o", (tmp / "all").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string all = readText(tmp / "all/materials/chrome/index.html");
  for (const char* file : {"theta_h.webp", "theta_h.svg", "theta_h.csv", "polar.webp", "polar.svg", "polar.csv"}) {
    EXPECT_TRUE(fs::is_regular_file(tmp / "all/materials/chrome/plots" / file)) << file;
    EXPECT_NE(all.find("plots/" + std::string(file)), std::string::npos) << file;
  }
  EXPECT_NE(all.find("Polar lobes"), std::string::npos);
  EXPECT_NE(readText(tmp / "all/materials/alum-bronze/index.html").find("No plots for this material"), std::string::npos);

  // The default: the pictures alone; --plot-kinds keeps the kinds named.
  r = runGlossy({"report", sheetsDir().string(), (tmp / "plots").string(), "--plot-kinds", "theta_h", "-o", (tmp / "lean").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string lean = readText(tmp / "lean/materials/chrome/index.html");
  EXPECT_TRUE(fs::is_regular_file(tmp / "lean/materials/chrome/plots/theta_h.webp"));
  for (const char* file : {"theta_h.svg", "theta_h.csv", "polar.webp", "polar.svg", "polar.csv"}) {
    EXPECT_FALSE(fs::exists(tmp / "lean/materials/chrome/plots" / file)) << file;
    EXPECT_EQ(lean.find("plots/" + std::string(file)), std::string::npos) << file;
  }
  EXPECT_EQ(lean.find("Polar lobes"), std::string::npos);
}

// A kind of plot that does not exist would drop every plot without a word.
TEST(ReportCli, UnknownPlotKindsAreRefused) {
  TempDir tmp;
  const RunResult r = runGlossy({"report", sheetsDir().string(), "--plot-kinds", "theta_h,bogus", "-o", (tmp / "site").string()});
  expectOneLineError(r, "--plot-kinds");
  EXPECT_NE(r.err.find("bogus"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(tmp / "site"));
}

// The site holds each pixel once, and plot pictures at the size the page shows them: a report of the
// default sheets and plots stays under 2 MB a material (docs/report.md has the figures).
TEST(ReportCli, ImagesAreNotDuplicatedAndPlotPicturesAreScaled) {
  TempDir tmp;
  const fs::path plots = tmp / "plots/chrome";
  fs::create_directories(plots);
  {
    // A picture as wide as glossy plot's (1.5 px per SVG unit).
    OIIO::ImageBuf wide(OIIO::ImageSpec(1600, 1000, 3, OIIO::TypeDesc::UINT8));
    const float white[3] = {1, 1, 1};
    OIIO::ImageBufAlgo::fill(wide, white);
    ASSERT_TRUE(wide.write((plots / "theta_h.png").string()));
  }
  writeText(plots / "plots.json", R"({"figures": [{"kind": "theta_h", "png": "theta_h.png"}]})");
  const RunResult r = report(sheetsDir(), tmp / "site", (tmp / "plots").string());
  ASSERT_EQ(r.status, 0) << r.err;
  const fs::path chrome = tmp / "site/materials/chrome";
  const RgbImage picture = readRgbImage(chrome / "plots/theta_h.webp");
  EXPECT_EQ(picture.width, 960);
  EXPECT_EQ(picture.height, 600);
  // The panels and the part below them are the sheet's PNG, each pixel once.
  const SheetRecord sheet = readSheetRecord(sheetsDir() / "chrome.exr");
  const RgbImage png = readRgbImage(sheetsDir() / "chrome.png");
  const RgbImage lower = readRgbImage(chrome / "sheet-lower.png");
  int64_t pixels = int64_t(lower.width) * lower.height;
  for (const PanelRecord& p : sheet.panels) pixels += int64_t(p.width) * p.height;
  EXPECT_EQ(pixels, int64_t(png.width) * png.height);
  EXPECT_EQ(lower.width, png.width);
  for (int y = 0; y < lower.height; ++y)
    for (int x = 0; x < lower.width; ++x)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(lower.at(x, y)[c], png.at(x, y + sheet.panelsBottom)[c]) << x << "," << y;
}

TEST(ReportCli, ReplacesAnEarlierReportAndLeavesItWhenTheInputIsBad) {
  TempDir tmp;
  copySheets(tmp / "sheets");
  ASSERT_EQ(report(tmp / "sheets", tmp / "site").status, 0);
  writeText(tmp / "site/notes.txt", "the user's own");
  fs::remove(tmp / "sheets/chrome.exr");
  fs::remove(tmp / "sheets/chrome.png");
  const RunResult again = report(tmp / "sheets", tmp / "site/");
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(readText(tmp / "site/notes.txt"), "the user's own") << "a file glossy did not write is never deleted";
  EXPECT_FALSE(fs::exists(tmp / "site/materials/chrome")) << "the earlier report's files no longer made are removed";
  EXPECT_TRUE(fs::exists(tmp / "site/materials/alum-bronze/index.html"));
  EXPECT_EQ(readText(tmp / "site/.glossy-manifest").find("chrome"), std::string::npos);
  for (const auto& e : fs::recursive_directory_iterator(tmp.path()))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();

  // A corrupt sheet: refused, naming it, and the site stays as it was.
  const std::string before = readText(tmp / "site/index.html");
  writeText(tmp / "sheets/broken.exr", "not an EXR at all");
  writeText(tmp / "sheets/broken.png", "");
  expectOneLineError(report(tmp / "sheets", tmp / "site"), "broken.exr");
  EXPECT_EQ(readText(tmp / "site/index.html"), before);
  // Cut short: the PNG's header reads, its pixels do not.
  fs::remove(tmp / "sheets/broken.exr");
  fs::remove(tmp / "sheets/broken.png");
  copySheets(tmp / "short");
  fs::remove(tmp / "short/alum-bronze.exr");
  fs::remove(tmp / "short/alum-bronze.png");
  const std::string whole = readText(tmp / "short/chrome.png");
  writeText(tmp / "short/chrome.png", whole.substr(0, whole.size() * 2 / 3));
  expectOneLineError(report(tmp / "short", tmp / "site"), "chrome.png");
  EXPECT_EQ(readText(tmp / "site/index.html"), before);
  EXPECT_FALSE(fs::exists(tmp / "site/materials/chrome"));
  for (const auto& e : fs::recursive_directory_iterator(tmp.path()))
    EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST(ReportCli, BadInputIsRefusedBeforeWriting) {
  TempDir tmp;
  expectOneLineError(report(tmp / "missing", tmp / "site"), "missing");
  fs::create_directories(tmp / "empty");
  expectOneLineError(report(tmp / "empty", tmp / "site"), "holds no sheets");
  copySheets(tmp / "sheets");
  writeText(tmp / "file", "x");
  expectOneLineError(report(tmp / "sheets", tmp / "file"), "-o " + (tmp / "file").string());
  fs::create_directories(tmp / "other");
  writeText(tmp / "other/precious.txt", "keep me");
  expectOneLineError(report(tmp / "sheets", tmp / "other"), "not writing into it");
  EXPECT_EQ(readText(tmp / "other/precious.txt"), "keep me");
  expectOneLineError(report(tmp / "sheets", tmp / "site", (tmp / "no-plots").string()), "no-plots");
  // plots.json naming a file outside its folder, or missing.
  fs::create_directories(tmp / "plots/chrome");
  writeText(tmp / "plots/chrome/plots.json", R"({"figures": [{"kind": "polar", "png": "../../file"}]})");
  expectOneLineError(report(tmp / "sheets", tmp / "site", (tmp / "plots").string()), "not a plain file name");
  writeText(tmp / "plots/chrome/plots.json", R"({"figures": [{"kind": "polar", "png": "absent.png"}]})");
  expectOneLineError(report(tmp / "sheets", tmp / "site", (tmp / "plots").string()), "absent.png");
  writeText(tmp / "plots/chrome/plots.json", R"({"figures": [)");
  expectOneLineError(report(tmp / "sheets", tmp / "site", (tmp / "plots").string()), "plots.json");
  fs::remove_all(tmp / "plots");
  // A sheet whose PNG is missing, or whose name is not a material name.
  fs::remove(tmp / "sheets/chrome.png");
  expectOneLineError(report(tmp / "sheets", tmp / "site"), "chrome.png");
  fs::copy_file(tmp / "sheets/alum-bronze.png", tmp / "sheets/chrome.png");
  {
    OIIO::ImageBuf buf((tmp / "sheets/chrome.exr").string());
    ASSERT_TRUE(buf.read(0, 0, true));
    buf.specmod().attribute("glossy:materialName", "bad name<x>");
    ASSERT_TRUE(buf.write((tmp / "sheets/renamed.exr").string()));
    fs::copy_file(tmp / "sheets/chrome.png", tmp / "sheets/renamed.png");
  }
  expectOneLineError(report(tmp / "sheets", tmp / "site"), "renamed.exr");
  EXPECT_FALSE(fs::exists(tmp / "site"));
}

namespace {

// A copy of the fixture's sheet `from` (NAME.exr and its PNG) as `to`.exr, with header attributes changed.
void modifiedSheet(const std::string& from, const fs::path& to, const std::vector<std::pair<std::string, std::string>>& attributes) {
  fs::create_directories(to.parent_path());
  OIIO::ImageBuf buf((sheetsDir() / (from + ".exr")).string());
  ASSERT_TRUE(buf.read(0, 0, true));
  for (const auto& [name, value] : attributes) buf.specmod().attribute(name, value);
  ASSERT_TRUE(buf.write(fs::path(to).replace_extension(".exr").string()));
  fs::copy_file(sheetsDir() / (from + ".png"), fs::path(to).replace_extension(".png"), fs::copy_options::overwrite_existing);
}

}  // namespace

// Every size and offset from a sheet's header is checked in 64 bits: a box whose y + height overflows an
// int cut a panel from memory outside the image.
TEST(ReportInput, BoxesBeyondTheImageAreRefusedWhateverTheirSize) {
  TempDir tmp;
  for (const char* box : {"0 2147483647 32 32", "2147483647 0 32 32", "0 0 4294967328 32", "0 0 99999999999999999999 32", "-1 0 32 32",
                          "0 1 32 32", "0 0 32", "0 0 32.5 32"}) {
    SCOPED_TRACE(box);
    fs::remove_all(tmp / "sheets");
    modifiedSheet("chrome", tmp / "sheets/chrome", {{"glossy:panel.smooth_E2.box", box}});
    expectOneLineError(report(tmp / "sheets", tmp / "site"), "chrome.exr");
    EXPECT_FALSE(fs::exists(tmp / "site"));
    expectOneLineError(runGlossy({"merge", "sheets", (tmp / "sheets").string(), "--csv", (tmp / "t.csv").string()}), "chrome.exr");
    EXPECT_FALSE(fs::exists(tmp / "t.csv"));
  }
}

// A figure is read only inside its domain: a negative relative RMSE, a ꟻLIP above 1 or a reversed interval
// is a crafted or corrupt sheet, refused naming the file and the figure rather than analysed as real.
TEST(ReportInput, FiguresOutsideTheirDomainAreRefused) {
  TempDir tmp;
  const std::string e = "glossy:error.smooth_E2.";
  for (const auto& [key, value] : std::vector<std::pair<std::string, std::string>>{{e + "relativeRmse", "-0.25"},
                                                                                 {e + "relativeRmseNoisy", "-1"},
                                                                                 {e + "flip", "1.5"},
                                                                                 {e + "luminanceRatio", "-2"},
                                                                                 {e + "E2", "-3"},
                                                                                 {e + "relativeRmseCi", "0.5 0.1"},
                                                                                 {e + "relativeRmseCi", "-0.1 0.2"},
                                                                                 {e + "flipCi", "0.2 0.1"},
                                                                                 {e + "deltaEItp", "-1"},
                                                                                 {e + "ssim", "1.5"},
                                                                                 {e + "ssimCi", "0.9 0.8"},
                                                                                 {"glossy:flipNoiseFloor", "2"}}) {
    SCOPED_TRACE(key + " = " + value);
    fs::remove_all(tmp / "sheets");
    modifiedSheet("chrome", tmp / "sheets/chrome", {{key, value}});
    RunResult r = report(tmp / "sheets", tmp / "site");
    expectOneLineError(r, "chrome.exr");
    EXPECT_NE(r.err.find(key), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp / "site"));
    r = runGlossy({"merge", "sheets", (tmp / "sheets").string(), "--csv", (tmp / "t.csv").string()});
    expectOneLineError(r, "chrome.exr");
    EXPECT_NE(r.err.find(key), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(tmp / "t.csv"));
  }
  // The edges of a domain are figures a sheet can carry.
  fs::remove_all(tmp / "sheets");
  modifiedSheet("chrome", tmp / "sheets/chrome", {{e + "relativeRmse", "0"}, {e + "flip", "1"}, {e + "luminanceRatioCi", "-0.5 1.5"}});
  EXPECT_EQ(report(tmp / "sheets", tmp / "site").status, 0);
}

// The material's name is the sheet's own (glossy:materialName), not its file name; two sheets of one
// material, or a name that cannot name a page, are refused.
TEST(ReportInput, TheMaterialNameComesFromTheSheet) {
  TempDir tmp;
  modifiedSheet("chrome", tmp / "sheets/my-render", {});
  ASSERT_EQ(report(tmp / "sheets", tmp / "site").status, 0);
  EXPECT_TRUE(fs::is_regular_file(tmp / "site/materials/chrome/index.html"));
  EXPECT_FALSE(fs::exists(tmp / "site/materials/my-render"));
  EXPECT_NE(readText(tmp / "site/index.html").find(">chrome</a>"), std::string::npos);

  modifiedSheet("chrome", tmp / "sheets/chrome-again", {});
  RunResult r = report(tmp / "sheets", tmp / "site");
  expectOneLineError(r, "chrome-again.exr");
  EXPECT_NE(r.err.find("my-render.exr"), std::string::npos) << r.err;
  expectOneLineError(runGlossy({"merge", "sheets", (tmp / "sheets").string(), "--csv", (tmp / "t.csv").string()}), "chrome-again.exr");
  fs::remove(tmp / "sheets/chrome-again.exr");
  modifiedSheet("chrome", tmp / "sheets/evil", {{"glossy:materialName", "../../escape"}});
  expectOneLineError(report(tmp / "sheets", tmp / "site"), "evil.exr");
  EXPECT_FALSE(fs::exists(tmp / "escape"));
}

// One index, one set of medians: over sheets made alike only. The settings are shown on the index.
TEST(ReportInput, SheetsMadeWithDifferentSettingsAreRefused) {
  TempDir tmp;
  copySheets(tmp / "sheets");
  ASSERT_EQ(report(tmp / "sheets", tmp / "site").status, 0);
  const std::string index = readText(tmp / "site/index.html");
  EXPECT_NE(index.find("Every sheet made with: scene preview.gltf; lighting default sky; panel size 32x32; samples per pixel 8; seed 1"),
            std::string::npos);
  const std::string settings = readImageAttribute(sheetsDir() / "chrome.exr", "glossy:settings");
  for (const auto& [from, to, what] : {std::tuple{"size=32x32", "size=64x64", "panel size"}, std::tuple{"spp=8", "spp=1024", "samples per pixel"},
                                       std::tuple{"seed=1", "seed=2", "seed"}}) {
    SCOPED_TRACE(what);
    std::string changed = settings;
    ASSERT_NE(changed.find(from), std::string::npos) << settings;
    changed.replace(changed.find(from), std::string(from).size(), to);
    modifiedSheet("chrome", tmp / "sheets/chrome", {{"glossy:settings", changed}});
    const RunResult r = report(tmp / "sheets", tmp / "site");
    expectOneLineError(r, what);
    EXPECT_NE(r.err.find("alum-bronze.exr"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("chrome.exr"), std::string::npos) << r.err;
    EXPECT_EQ(readText(tmp / "site/index.html"), index);
  }
  // The scene's folder is not a setting: the same scene from another checkout agrees.
  std::string moved = settings;
  const size_t scene = moved.find("scene=");
  moved.replace(scene, moved.find(';', scene) - scene, "scene=/elsewhere/scenes/preview.gltf");
  modifiedSheet("chrome", tmp / "sheets/chrome", {{"glossy:settings", moved}});
  EXPECT_EQ(report(tmp / "sheets", tmp / "site").status, 0);
}

// The report reads regular files inside its input folders only: a symlink leading out of them would copy
// any file into a site meant for publishing, a FIFO would block it forever.
TEST(ReportInput, LinksOutOfTheInputFoldersAndSpecialFilesAreRefused) {
  TempDir tmp;
  copySheets(tmp / "sheets");
  writeText(tmp / "secret.csv", "private,data\n");
  const fs::path plots = tmp / "plots/chrome";
  fs::create_directories(plots);
  fs::copy_file(sheetsDir() / "chrome.png", plots / "theta_h.png");
  writeText(plots / "plots.json", R"({"figures": [{"kind": "theta_h", "png": "theta_h.png", "csv": "theta_h.csv"}]})");
  fs::create_symlink(tmp / "secret.csv", plots / "theta_h.csv");
  expectOneLineError(runGlossy({"report", (tmp / "sheets").string(), (tmp / "plots").string(), "--plot-data", "-o", (tmp / "site").string()}),
                     "theta_h.csv");
  EXPECT_FALSE(fs::exists(tmp / "site"));
  // A link inside the folder is followed.
  fs::remove(plots / "theta_h.csv");
  writeText(tmp / "plots/data.csv", "x,y\n");
  fs::create_symlink("../data.csv", plots / "theta_h.csv");
  RunResult r = runGlossy({"report", (tmp / "sheets").string(), (tmp / "plots").string(), "--plot-data", "-o", (tmp / "site").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readText(tmp / "site/materials/chrome/plots/theta_h.csv"), "x,y\n");

  // Sheets: a link out, a FIFO as a sheet, a FIFO as plots.json: refused at once, naming the file.
  fs::copy_file(tmp / "sheets/chrome.png", tmp / "outside.png");
  fs::copy_file(tmp / "sheets/chrome.exr", tmp / "outside.exr");
  fs::create_symlink(tmp / "outside.exr", tmp / "sheets/linked.exr");
  fs::copy_file(tmp / "sheets/chrome.png", tmp / "sheets/linked.png");
  expectOneLineError(report(tmp / "sheets", tmp / "site2"), "linked.exr");
  fs::remove(tmp / "sheets/linked.exr");
  fs::remove(tmp / "sheets/linked.png");
  ASSERT_EQ(::mkfifo((tmp / "sheets/fifo.exr").c_str(), 0644), 0);
  expectOneLineError(runGlossy({"report", (tmp / "sheets").string(), "-o", (tmp / "site2").string()}), "fifo.exr");
  expectOneLineError(runGlossy({"merge", "sheets", (tmp / "sheets").string(), "--csv", (tmp / "t.csv").string()}), "fifo.exr");
  fs::remove(tmp / "sheets/fifo.exr");
  fs::remove(plots / "plots.json");
  ASSERT_EQ(::mkfifo((plots / "plots.json").c_str(), 0644), 0);
  expectOneLineError(report(tmp / "sheets", tmp / "site2", (tmp / "plots").string()), "plots.json");
  EXPECT_FALSE(fs::exists(tmp / "site2"));
}

TEST(ReportSummary, CountsClosestAndTiesApartAndTakesMedians) {
  auto sheet = [](const std::string& name, const std::string& verdict, double a, std::optional<double> b) {
    SheetRecord s;
    s.name = name;
    s.verdict = verdict;
    PanelRecord m;
    m.layer = "measured", m.label = "Measured", m.fit = "measured";
    PanelRecord pa;
    pa.layer = "smooth_E2", pa.label = "Smooth E2", pa.fit = "smooth:E2";
    pa.relativeRmse.value = a;
    PanelRecord pb;
    pb.layer = "cook_torrance_E2", pb.label = "CT E2", pb.fit = "cook-torrance:E2";
    pb.relativeRmse.value = b;
    s.panels = {m, pa, pb};
    return s;
  };
  const std::vector<SheetRecord> sheets = {sheet("a", "closest: Smooth E2", 0.1, 0.3), sheet("b", "tie: Smooth E2, CT E2", 0.2, 0.2),
                                                   sheet("c", "closest: CT E2", 0.4, std::nullopt), sheet("d", "no measured panel", 0.3, 0.5)};
  EXPECT_EQ(sheets[1].closestLayers(), (std::vector<std::string>{"smooth_E2", "cook_torrance_E2"}));
  EXPECT_TRUE(sheets[1].isTie());
  EXPECT_TRUE(sheets[3].closestLayers().empty());
  const std::vector<report::ModelSummary> s = report::summarizeModels(sheets);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].layer, "smooth_E2");
  EXPECT_EQ(s[0].closest, 1);
  EXPECT_EQ(s[0].ties, 1);
  EXPECT_EQ(s[0].compared, 4);
  EXPECT_DOUBLE_EQ(*s[0].medianRelativeRmse, 0.25);
  EXPECT_EQ(s[1].closest, 1);
  EXPECT_EQ(s[1].ties, 1);
  EXPECT_EQ(s[1].compared, 3);
  EXPECT_DOUBLE_EQ(*s[1].medianRelativeRmse, 0.3);
  EXPECT_FALSE(s[0].medianFlip.has_value());
  EXPECT_FALSE(report::median({}).has_value());
}

TEST(ReportHtml, EscapesAndFormats) {
  EXPECT_EQ(report::escapeHtml("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(report::shortNumber(std::nullopt), "–");
  EXPECT_EQ(report::shortNumber(0.123456), "0.123");
  EXPECT_EQ(report::sortValue(std::nullopt), "");
  EXPECT_EQ(report::sortValue(std::numeric_limits<double>::quiet_NaN()), "");
}

}  // namespace glossy::test
