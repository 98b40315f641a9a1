// glossy plot (renderer/plot/, docs/plots.md): its CSVs hold what `glossy eval` computes at the direction
// pairs they name (so a plot cannot lie), its albedo at V = N is the spec's reference table, the SVGs are
// XML with axes, legend and a caption naming material and data source, and bad input is refused as such.
#include "materials/core/text.h"
#include "materials/models/albedo.h"
#include "renderer/plot/chart.h"
#include "renderer/plot/directional_albedo.h"
#include "renderer/plot/plot_csv.h"
#include "renderer/plot/rusinkiewicz.h"
#include "renderer/sheet/comparison_grid.h"
#include "materials/params/material_file.h"
#include "support/test_support.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace glossy::test {
namespace {

using Row = std::map<std::string, std::string>;

bool hasValue(const Row& r, const std::string& c) { return r.count(c) && !r.at(c).empty(); }
double num(const Row& r, const std::string& c) { return *parseNumber(r.at(c)); }

std::string pairOf(const Row& r) {
  return r.at("Lx") + "," + r.at("Ly") + "," + r.at("Lz") + "," + r.at("Vx") + "," + r.at("Vy") + "," + r.at("Vz");
}

nlohmann::json readIndex(const std::filesystem::path& dir) { return nlohmann::json::parse(readText(dir / "plots.json")); }

// A check of one CSV cell against eval: which file and row, the column, and what the cell holds.
struct Cell {
  std::string where;
  std::string value;  // empty: the plot says "no value" (an unmeasured bin)
  double scale;       // the cell is eval's value × scale (the polar figure's cos θ_i; else 1)
};

// Every cell of every BRDF column in the figures' CSVs, checked against `glossy eval` for that BRDF: one eval
// run per BRDF over all its pairs. `evalArgs` maps a column (panel label) to the eval options naming it.
void checkCsvsAgainstEval(const std::filesystem::path& dir, const std::map<std::string, std::vector<std::string>>& evalArgs) {
  const nlohmann::json index = readIndex(dir);
  std::map<std::string, std::pair<std::string, std::vector<Cell>>> requests;  // column → (stdin, cells)
  size_t checked = 0;
  for (const auto& f : index["figures"]) {
    if (f["kind"] == "albedo") continue;  // integrated over L: checked against the spec's table instead
    const std::string csv = f["csv"];
    const auto rows = readCsv(dir / csv);
    ASSERT_FALSE(rows.empty()) << csv;
    for (size_t i = 0; i < rows.size(); ++i) {
      const Row& r = rows[i];
      ASSERT_GT(num(r, "Lz"), 0.0) << csv << " row " << i << ": a pair below the horizon was written";
      ASSERT_GT(num(r, "Vz"), 0.0) << csv << " row " << i;
      if (i == 0)
        for (const auto& [column, value] : r) {
          // Every column is an angle, a direction, the log-ratio, or a BRDF that eval is asked about.
          const bool known = column.starts_with("theta_") || column.starts_with("phi_") || column == "log10_ratio" ||
                             (column.size() == 2 && (column[0] == 'L' || column[0] == 'V'));
          EXPECT_TRUE(known || evalArgs.count(column)) << csv << ": column '" << column << "' is not checked";
        }
      for (const auto& [column, args] : evalArgs) {
        if (!r.count(column)) continue;
        auto& [input, cells] = requests[column];
        input += pairOf(r) + "\n";
        cells.push_back({csv + " row " + std::to_string(i + 2), r.at(column), f["kind"] == "polar" ? num(r, "Lz") : 1.0});
      }
    }
  }
  for (const auto& [column, request] : requests) {
    const auto& [input, cells] = request;
    const RunResult r = runGlossy(evalArgs.at(column), input);
    ASSERT_EQ(r.status, 0) << column << ": " << r.err;
    std::istringstream out(r.out);
    std::string line;
    for (const Cell& c : cells) {
      ASSERT_TRUE(std::getline(out, line)) << column << ": eval gave fewer lines than pairs";
      const auto rgb = parseNumberList(line);
      ASSERT_TRUE(rgb && rgb->size() == 3) << line;
      const double expected = luminance(Rgb((*rgb)[0], (*rgb)[1], (*rgb)[2])) * c.scale;
      if (c.value.empty()) {
        // No value in the plot: the measured table has no data there, which eval reports as 0.
        EXPECT_EQ((*rgb)[0] + (*rgb)[1] + (*rgb)[2], 0.0) << c.where << " " << column;
        continue;
      }
      const double got = *parseNumber(c.value);
      EXPECT_NEAR(got, expected, 1e-9 * std::abs(expected) + 1e-300) << c.where << " " << column;
      ++checked;
    }
  }
  EXPECT_GT(checked, 10000u);
}

// The log-ratio column is log10 of the two columns beside it.
void checkLogRatios(const std::filesystem::path& dir) {
  const nlohmann::json index = readIndex(dir);  // kept alive: a range-for over a temporary's member dangles
  for (const auto& f : index["figures"]) {
    if (f["kind"] != "image_slice") continue;
    const auto rows = readCsv(dir / std::string(f["csv"]));
    for (const Row& r : rows) {
      if (!r.count("log10_ratio")) break;
      // The fit's column: the one that is neither an angle (theta_*), a direction (Lx, …), nor the two others.
      std::string fit;
      for (const auto& [k, v] : r)
        if (k != "Measured" && k != "log10_ratio" && k.find('_') == std::string::npos && k.size() > 2) fit = k;
      ASSERT_FALSE(fit.empty());
      if (!hasValue(r, "log10_ratio")) continue;
      EXPECT_NEAR(num(r, "log10_ratio"), std::log10(num(r, fit) / num(r, "Measured")), 1e-12);
    }
  }
}

// The fits a plot draws by default: the comparison grid's, measured aside.
size_t gridFits() { return sheetPanels().size() - 1; }

std::map<std::string, std::vector<std::string>> fitArgs(const std::filesystem::path& material) {
  const MaterialFile m = loadMaterialFile(material);
  std::map<std::string, std::vector<std::string>> args;
  // Each fit under the label its curve has (the grid's: "CT E2", "CT E2 (glossy fit)").
  for (const Fit& f : m.fits) args[SheetPanel::ofFit(f.id).label] = {"eval", "--material", material.string(), "--fit", f.id.str()};
  return args;
}

// alum-bronze plotted with its measured table, once for the tests that read it.
const std::filesystem::path& alumBronzePlots() {
  static TempDir tmp;
  static const RunResult r = runGlossy({"plot", "--material", (materialsDir() / "alum-bronze.toml").string(), "--merl-dir",
                                        (sharedDir() / "merl").string(), "-o", (tmp / "out").string()});
  EXPECT_EQ(r.status, 0) << r.err;
  static const std::filesystem::path out = tmp / "out";
  return out;
}

TEST(PlotCli, CsvMatchesEvalWithMeasuredData) {
  GLOSSY_REQUIRE_SHARED("merl/alum-bronze.binary.xz");
  const auto material = materialsDir() / "alum-bronze.toml";
  const std::filesystem::path dir = alumBronzePlots();
  ASSERT_TRUE(std::filesystem::exists(dir / "plots.json"));
  const nlohmann::json index = readIndex(dir);
  EXPECT_EQ(index["material"], "alum-bronze");
  EXPECT_EQ(index["channel"], "luminance");
  EXPECT_NE(std::string(index["measured"]).find("MERL (NBRDF reconstruction)"), std::string::npos) << index["measured"];
  std::multiset<std::string> kinds;
  for (const auto& f : index["figures"]) {
    kinds.insert(f["kind"]);
    std::set<std::string> keys;
    for (const auto& [k, v] : f.items()) keys.insert(k);
    EXPECT_EQ(keys, (std::set<std::string>{"kind", "title", "caption", "svg", "png", "csv"}));
    for (const char* file : {"svg", "csv"}) EXPECT_TRUE(std::filesystem::exists(dir / std::string(f[file])));
    if (!f["png"].is_null()) {
      EXPECT_TRUE(std::filesystem::exists(dir / std::string(f["png"])));
    }
  }
  EXPECT_EQ(kinds.count("theta_h"), 1u);
  // The measured data and the grid's six fits (not glossy's refits or its GGX fit beside them: --panels).
  EXPECT_EQ(kinds.count("image_slice"), 1u + gridFits());
  EXPECT_EQ(kinds.count("albedo"), 1u);
  EXPECT_EQ(kinds.count("polar"), 1u);

  auto args = fitArgs(material);
  args["Measured"] = {"eval", "--measured", (sharedDir() / "merl/alum-bronze.binary.xz").string()};
  checkCsvsAgainstEval(dir, args);
  checkLogRatios(dir);
}

// A copy of a library material without its measured data (and away from the embedded networks): the fits
// alone, as a material file with no table gives them.
std::filesystem::path withoutMeasured(const TempDir& tmp, const std::string& name) {
  std::string text = readText(materialsDir() / (name + ".toml"));
  text = std::regex_replace(text, std::regex("\nmeasured = [^\n]*"), "");
  const auto path = tmp / (name + ".toml");
  writeText(path, text);
  return path;
}

TEST(PlotCli, CsvMatchesEvalWithoutMeasuredData) {
  TempDir tmp;
  const auto material = withoutMeasured(tmp, "chrome");
  const RunResult r = runGlossyIn(tmp.path(), {"GLOSSY_MERL_DIR"}, {"plot", "--material", material.string(), "-o", (tmp / "out").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json index = readIndex(tmp / "out");
  size_t slices = 0;
  for (const auto& f : index["figures"]) {
    if (f["kind"] == "image_slice") {
      ++slices;
      EXPECT_NE(std::string(f["caption"]).find("not drawn"), std::string::npos) << f["caption"];
    }
    EXPECT_NE(std::string(f["caption"]).find("measured data: none"), std::string::npos) << f["caption"];
    EXPECT_EQ(readCsv(tmp / "out" / std::string(f["csv"]))[0].count("Measured"), 0u) << f["csv"];
  }
  EXPECT_EQ(slices, gridFits());  // one per fit of the grid
  checkCsvsAgainstEval(tmp / "out", fitArgs(material));
}

// chrome plotted from the network embedded beside it, in a folder with nothing else (as on a fresh clone):
// a mirror lobe near 10^4 over diffuse floors near 10^-4, which a fixed span of decades cuts off.
const std::filesystem::path& chromePlots() {
  static TempDir tmp;
  static const RunResult r = runGlossyIn(tmp.path(), {"GLOSSY_MERL_DIR"},
                                         {"plot", "--material", (materialsDir() / "chrome.toml").string(), "-o", (tmp / "out").string()});
  EXPECT_EQ(r.status, 0) << r.err;
  static const std::filesystem::path out = tmp / "out";
  return out;
}

// The log scale a caption states: "… 10^lo to 10^hi …".
std::pair<int, int> captionDecades(const std::string& caption) {
  std::smatch m;
  if (!std::regex_search(caption, m, std::regex("10\\^(-?[0-9]+) to 10\\^(-?[0-9]+)"))) {
    ADD_FAILURE() << "the caption names no range of decades: " << caption;
    return {0, 0};
  }
  return {std::stoi(m[1]), std::stoi(m[2])};
}

// The positive values of a figure CSV's BRDF columns (not the direction, the angles or the log-ratio).
std::map<std::string, std::vector<double>> brdfColumns(const std::filesystem::path& csv) {
  std::map<std::string, std::vector<double>> out;
  for (const Row& r : readCsv(csv))
    for (const auto& [column, value] : r) {
      if (column.size() == 2 || column.starts_with("theta_") || column.starts_with("phi_") || column == "log10_ratio") continue;
      if (!value.empty() && *parseNumber(value) > 0.0) out[column].push_back(*parseNumber(value));
    }
  return out;
}

double percentile(std::vector<double> v, double q) {
  const size_t n = std::min(v.size() - 1, size_t(q * double(v.size())));
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(n), v.end());
  return v[n];
}

// The θh and polar figures' log axes follow the data: every curve's floor (its 2nd percentile) lies on the
// axis, and the lowest decade is one some value reaches.
TEST(PlotRange, EveryCurvesFloorIsOnTheLogAxes) {
  const auto dir = chromePlots();
  const nlohmann::json index = readIndex(dir);
  size_t checked = 0;
  for (const auto& f : index["figures"]) {
    if (f["kind"] != "theta_h" && f["kind"] != "polar") continue;
    const auto [lo, hi] = captionDecades(f["caption"]);
    double lowest = std::numeric_limits<double>::infinity();
    for (const auto& [column, values] : brdfColumns(dir / std::string(f["csv"]))) {
      EXPECT_GE(percentile(values, 0.02), std::pow(10.0, lo)) << f["kind"] << " " << column << ": its floor is cut off";
      EXPECT_LE(*std::max_element(values.begin(), values.end()), std::pow(10.0, hi)) << f["kind"] << " " << column;
      lowest = std::min(lowest, *std::min_element(values.begin(), values.end()));
      ++checked;
    }
    EXPECT_LT(lowest, std::pow(10.0, lo + 1)) << f["kind"] << ": the axis reaches decades no value is in";
    EXPECT_LE(hi - lo, plot::kMaxDecades);
  }
  // Measured and the grid's fits, in two figures.
  EXPECT_EQ(checked, 2u * (1u + gridFits()));
}

// The image slices' colour scale is what their caption says: the decades holding the 0.5th to the 99.5th
// percentile of all the slices' values.
TEST(PlotRange, ImageSliceCaptionStatesItsColourScale) {
  const auto dir = chromePlots();
  const nlohmann::json index = readIndex(dir);
  std::vector<double> all;
  std::vector<std::pair<int, int>> stated;
  for (const auto& f : index["figures"]) {
    if (f["kind"] != "image_slice") continue;
    stated.push_back(captionDecades(f["caption"]));
    // Each slice's own BRDF: the column after the angles (Measured beside a fit is the measured slice's).
    const std::string title = f["title"];
    for (const auto& [column, values] : brdfColumns(dir / std::string(f["csv"])))
      if (title.find("of " + column + ",") != std::string::npos) all.insert(all.end(), values.begin(), values.end());
  }
  const size_t slices = 1 + gridFits();  // its network's, and each fit's
  ASSERT_EQ(stated.size(), slices);
  ASSERT_GT(all.size(), slices * 8000u);
  const int lo = int(std::floor(std::log10(percentile(all, 0.005)))), hi = int(std::ceil(std::log10(percentile(all, 0.995))));
  for (const auto& s : stated) EXPECT_EQ(s, std::make_pair(lo, hi));
}

// --decades N: every log scale spans the N decades below its top, and the caption says so.
TEST(PlotRange, DecadesOptionSetsEverySpan) {
  TempDir tmp;
  const auto material = withoutMeasured(tmp, "chrome");
  const RunResult r = runGlossyIn(tmp.path(), {"GLOSSY_MERL_DIR"},
                                  {"plot", "--material", material.string(), "--decades", "4", "--figures", "theta_h,polar,image_slice",
                                   "-o", (tmp / "out").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json index = readIndex(tmp / "out");
  // θh and polar, and an image slice per fit of the grid.
  ASSERT_EQ(index["figures"].size(), 2u + gridFits());
  for (const auto& f : index["figures"]) {
    const auto [lo, hi] = captionDecades(f["caption"]);
    EXPECT_EQ(hi - lo, 4) << f["caption"];
    EXPECT_NE(std::string(f["caption"]).find("the 4 decades below the peak (--decades)"), std::string::npos) << f["caption"];
  }
  for (const char* bad : {"0", "-3", "x", "1e9"}) {
    const RunResult b = runGlossyIn(tmp.path(), {"GLOSSY_MERL_DIR"},
                                    {"plot", "--material", material.string(), "--decades", bad, "-o", (tmp / "bad").string()});
    expectOneLineError(b, "--decades");
  }
}

// Captions, titles, SVGs and plots.json go into papers and sites: they name the data by file, never by
// where it lies on this machine.
TEST(PlotCli, NoLocalPathInWhatItWrites) {
  const auto dir = chromePlots();
  const nlohmann::json index = readIndex(dir);
  EXPECT_EQ(index["measured"], "MERL (NBRDF reconstruction) chrome.nbrdf");
  const std::string local = sourceDir().string();
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".png") continue;
    const std::string text = readText(entry.path());
    EXPECT_EQ(text.find(local), std::string::npos) << entry.path() << " names " << local;
    EXPECT_EQ(text.find(dir.parent_path().string()), std::string::npos) << entry.path();
  }
}

// docs/plots.md's pipeline: a CSV's rows without the header, cut to their first six columns, are
// `glossy eval`'s input, and eval gives the column the figure drew.
TEST(PlotCli, CsvRowsPipeIntoEval) {
  TempDir tmp;
  const auto material = withoutMeasured(tmp, "chrome");
  const RunResult r = runGlossyIn(tmp.path(), {"GLOSSY_MERL_DIR"},
                                  {"plot", "--material", material.string(), "--figures", "theta_h,polar,image_slice", "-o", (tmp / "out").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  for (const std::string name : {"theta_h", "polar", "image_slice_cook_torrance_E2"}) {
    const auto csv = tmp / "out" / (name + ".csv");
    const auto rows = readCsv(csv);
    ASSERT_FALSE(rows.empty()) << csv;
    const std::string header = readText(csv).substr(0, readText(csv).find('\n'));
    EXPECT_TRUE(header.starts_with("Lx,Ly,Lz,Vx,Vy,Vz,")) << header;
    const std::string out = (tmp / (name + ".eval")).string();
    const std::string cmd = "tail -n +2 " + shellQuote(csv.string()) + " | cut -d, -f1-6 | " + shellQuote(GLOSSY_EXE) +
                            " eval --material " + shellQuote(material.string()) + " --fit cook-torrance:E2 > " + shellQuote(out);
    ASSERT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::istringstream eval(readText(out));
    std::string line;
    for (size_t i = 0; i < rows.size(); ++i) {
      ASSERT_TRUE(std::getline(eval, line)) << name << ": eval gave fewer lines than rows";
      const auto rgb = parseNumberList(line);
      ASSERT_TRUE(rgb && rgb->size() == 3) << line;
      const double scale = name == "polar" ? num(rows[i], "Lz") : 1.0;  // the polar figure draws ρ cos θi
      const double want = luminance(Rgb((*rgb)[0], (*rgb)[1], (*rgb)[2])) * scale;
      EXPECT_NEAR(num(rows[i], "CT E2"), want, 1e-9 * std::abs(want) + 1e-300) << name << " row " << i + 2;
    }
  }
}

// The spec's "Reference values": directional albedo at V = N, red channel, of three materials' fits.
struct SpecAlbedo {
  std::string material, label;
  double red;
};
std::vector<SpecAlbedo> specAlbedos() {
  const auto spec = sharedDir() / "spec/models.md";
  std::vector<SpecAlbedo> out;
  if (!std::filesystem::exists(spec)) return out;
  std::istringstream in(readText(spec));
  std::string line;
  std::vector<std::string> header;
  bool inTable = false;
  auto cells = [](const std::string& l) {
    std::vector<std::string> c;
    std::stringstream s(l);
    std::string item;
    while (std::getline(s, item, '|')) {
      item.erase(0, item.find_first_not_of(' '));
      item.erase(item.find_last_not_of(' ') + 1);
      c.push_back(item);
    }
    return c;
  };
  while (std::getline(in, line)) {
    if (line.find("Reference values") != std::string::npos) inTable = true;
    else if (inTable && line.rfind("| material", 0) == 0) header = cells(line);
    else if (inTable && !header.empty() && line.rfind("| ", 0) == 0) {
      const auto c = cells(line);
      for (size_t i = 2; i < c.size() && i < header.size(); ++i)
        out.push_back({c[1], header[i], *parseNumber(c[i])});
    } else if (inTable && !header.empty() && line.rfind("|", 0) != 0) break;
  }
  return out;
}

TEST(PlotCli, AlbedoAtNormalIncidenceIsTheSpecTable) {
  const auto table = specAlbedos();
  if (table.empty()) GTEST_SKIP() << "the spec's reference table " << (sharedDir() / "spec/models.md") << " is absent";
  TempDir tmp;
  std::set<std::string> materials;
  for (const auto& s : table) materials.insert(s.material);
  size_t checked = 0;
  for (const std::string& name : materials) {
    const auto material = withoutMeasured(tmp, name);
    const auto out = tmp / ("out-" + name);
    const RunResult r = runGlossyIn(tmp.path(), {"GLOSSY_MERL_DIR"},
                                    {"plot", "--material", material.string(), "--channel", "R", "--figures", "albedo", "-o", out.string()});
    ASSERT_EQ(r.status, 0) << r.err;
    ASSERT_EQ(readIndex(out)["figures"].size(), 1u);
    const auto rows = readCsv(out / "albedo.csv");
    ASSERT_EQ(rows[0].at("theta_v_deg"), "0");
    for (const auto& s : table) {
      if (s.material != name) continue;
      // "AS E2" and friends: the table's labels are the sheet's.
      ASSERT_TRUE(rows[0].count(s.label)) << name << ": no column " << s.label;
      EXPECT_NEAR(num(rows[0], s.label), s.red, 0.5e-4 + 1e-9) << name << " " << s.label;
      ++checked;
    }
  }
  EXPECT_EQ(checked, table.size());
}

TEST(PlotAlbedo, LambertianIsItsReflectanceAtEveryAngle) {
  const double kd = 0.7;
  for (double deg : {0.0, 10.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.0})
    EXPECT_NEAR(plot::directionalAlbedo([&](const Vec3&, const Vec3&) { return kd * kInvPi; }, deg * kPi / 180.0), kd, 1e-9) << deg;
}

TEST(PlotAlbedo, AtNormalIncidenceMatchesTheOneDimensionalQuadrature) {
  for (const char* name : {"alum-bronze", "chrome", "aluminium"}) {
    const MaterialFile m = loadMaterialFile(materialsDir() / (std::string(name) + ".toml"));
    for (const Fit& f : m.fits) {
      const Brdf b = makeBrdf(f);
      const double a = plot::directionalAlbedo([&](const Vec3& L, const Vec3& V) { return eval(b, L, V).r; }, 0.0);
      // 1e-5: the microfacet fits' integrands have kinks that neither rule resolves beyond a few 1e-6 (the two
      // move by that much with the node count), a hundredth of the spec table's rounding.
      EXPECT_NEAR(a, albedoAtNormalIncidence(b).r, 1e-5 * albedoAtNormalIncidence(b).r) << name << " " << f.id.str();
    }
  }
}

// At an oblique view, against a brute-force midpoint sum over (θ_L, φ_L) fine enough for a 4° lobe.
TEST(PlotAlbedo, AtObliqueViewMatchesBruteForce) {
  const MaterialFile m = loadMaterialFile(materialsDir() / "alum-bronze.toml");
  const Brdf b = makeBrdf(*m.find(FitId::parse("cook-torrance:E2", "test")));
  for (double deg : {40.0, 70.0}) {
    const double tv = deg * kPi / 180.0;
    const Vec3 V(std::sin(tv), 0.0, std::cos(tv));
    const int nt = 1500, np = 3000;
    double sum = 0.0;
    for (int i = 0; i < nt; ++i) {
      const double t = (i + 0.5) * (kPi / 2) / nt, st = std::sin(t), ct = std::cos(t);
      for (int j = 0; j < np; ++j) {
        const double p = (j + 0.5) * 2 * kPi / np;
        sum += eval(b, Vec3(st * std::cos(p), st * std::sin(p), ct), V).r * ct * st;
      }
    }
    sum *= (kPi / 2 / nt) * (2 * kPi / np);
    const double quad = plot::directionalAlbedo([&](const Vec3& L, const Vec3& V2) { return eval(b, L, V2).r; }, tv);
    EXPECT_NEAR(quad, sum, 2e-4 * sum) << deg;
  }
}

// A value a log axis cannot show (0, negative, NaN) breaks the curve: no line is drawn through it as 0.
TEST(PlotChart, CurvesBreakAtMissingValues) {
  plot::SvgDocument svg(100, 100);
  const plot::PlotArea area{0, 0, 100, 100, plot::linearAxis(0, 10, 1, 0, "x"), plot::logAxis(-2, 2, "y")};
  plot::drawCurve(svg, area, {{1, 1.0}, {2, 2.0}, {3, 0.0}, {4, 3.0}, {5, 4.0}, {6, std::nan("")}, {7, 5.0}, {8, 6.0}}, {}, "c");
  const std::string text = svg.str();
  size_t lines = 0;
  for (size_t at = text.find("<polyline"); at != std::string::npos; at = text.find("<polyline", at + 1)) ++lines;
  EXPECT_EQ(lines, 3u) << text;
  EXPECT_EQ(text.find("nan"), std::string::npos);
  EXPECT_EQ(plot::decadeRange(0.02, 450.0, 3), std::make_pair(-2, 3));
  EXPECT_EQ(plot::decadeRange(2e-5, 450.0, 3), std::make_pair(-5, 3));     // down to the floor, however far
  EXPECT_EQ(plot::decadeRange(1e-30, 450.0, 3), std::make_pair(-9, 3));    // but no wider than kMaxDecades
  EXPECT_EQ(plot::decadeRange(0.5, 0.9, 3), std::make_pair(-3, 0));        // at least 3
  EXPECT_EQ(plot::decadeRange(2e-5, 450.0, 3, 4), std::make_pair(-1, 3));  // --decades 4
  EXPECT_EQ(plot::curveFloor({0.0, std::nan(""), 3.0, 2.0}), 2.0);
  std::vector<double> toHorizon(100, 1e-2);
  toHorizon[98] = 1e-9;  // the last point, where ρ cos θi falls to 0, is not the curve's floor
  EXPECT_EQ(plot::curveFloor(toHorizon), 1e-2);
}

TEST(PlotChart, TextIsEscapedAndCsvHasNoNonFiniteNumbers) {
  EXPECT_EQ(plot::xmlEscape("a<b>&\"c'\x01"), "a&lt;b&gt;&amp;&quot;c&apos;?");
  plot::CsvTable csv({"x", "a,b"});
  csv.add({1.5, std::nan("")});
  csv.add({std::numeric_limits<double>::infinity(), 0.1});
  EXPECT_EQ(csv.str(), "x,\"a,b\"\n1.5,\n,0.1\n");
  EXPECT_THROW(csv.add({1.0}), std::logic_error);
}

// The slices' (θh, θd, φd) → (L, V) is the inverse of the MERL lookup's coordinates.
TEST(PlotChart, HalfDifferenceAnglesRoundTripThroughTheMerlLookup) {
  for (int i = 0; i < 90; i += 7)
    for (int j = 0; j < 90; j += 11) {
      const double th = ((i + 0.5) / 90.0) * ((i + 0.5) / 90.0) * kPi / 2, td = (j + 0.5) * kPi / 180;
      const auto [L, V] = plot::directionsFromHalfDiff(th, td, (90.5) * kPi / 180);
      const MerlBin b = MerlTable::binOf(L, V);
      EXPECT_EQ(b.thetaH, i);
      EXPECT_EQ(b.thetaD, j);
      EXPECT_EQ(b.phiD, 90);
      EXPECT_NEAR(std::sqrt(L.x * L.x + L.y * L.y + L.z * L.z), 1.0, 1e-15);
      EXPECT_NEAR(std::sqrt(V.x * V.x + V.y * V.y + V.z * V.z), 1.0, 1e-15);
    }
}

// The SVGs are XML: an <svg> root, lines and text, every legend label, and a caption naming the material and
// the data source. Checked with Python's XML parser, which refuses anything malformed.
TEST(PlotSvg, ParsesWithAxesLegendAndCaption) {
  GLOSSY_REQUIRE_SHARED("merl/alum-bronze.binary.xz");
  if (!std::filesystem::exists(GLOSSY_TEST_PYTHON))
    GTEST_SKIP() << "the test Python " << GLOSSY_TEST_PYTHON << " is absent (scripts/test-tools creates it)";
  TempDir tmp;
  const std::filesystem::path dir = alumBronzePlots();
  ASSERT_TRUE(std::filesystem::exists(dir / "plots.json"));
  writeText(tmp / "check.py", R"PY(
import sys, json, os, xml.etree.ElementTree as ET
ns = "{http://www.w3.org/2000/svg}"
folder = sys.argv[1]
index = json.load(open(os.path.join(folder, "plots.json")))
for f in index["figures"]:
    root = ET.parse(os.path.join(folder, f["svg"])).getroot()
    assert root.tag == ns + "svg", f["svg"]
    texts = [("".join(t.itertext())) for t in root.iter(ns + "text")]
    alltext = " ".join(texts)
    assert len(list(root.iter(ns + "line"))) > 10, f["svg"] + ": no axes"
    for need in ["alum-bronze", "MERL (NBRDF reconstruction)", "channel luminance"]:
        assert need in alltext, f["svg"] + ": no " + need
    if f["kind"] != "image_slice":
        assert len(list(root.iter(ns + "polyline"))) >= 7, f["svg"] + ": curves missing"
        for label in ["Measured", "Microfacet E2", "Smooth E2", "AS E1", "AS E2", "CT E1", "CT E2"]:
            assert label in texts, f["svg"] + ": no legend entry " + label
        assert any(t.startswith("θ") and ("(degrees" in t or "angle" in t) for t in texts), f["svg"] + ": no axis label"
    else:
        assert len(list(root.iter(ns + "rect"))) > 100, f["svg"] + ": no image"
    if f["kind"] == "theta_h":
        assert "10" in texts and "ρ (1/sr)" in texts, f["svg"] + ": no log axis"
print("ok", len(index["figures"]))
)PY");
  const std::string cmd = std::string("'") + GLOSSY_TEST_PYTHON + "' '" + (tmp / "check.py").string() + "' '" + dir.string() +
                          "' > '" + (tmp / "py.out").string() + "' 2>&1";
  const int status = std::system(cmd.c_str());
  EXPECT_EQ(status, 0) << readText(tmp / "py.out");
  // θh, albedo, polar, and an image slice of the measured data and of each fit.
  EXPECT_EQ(readText(tmp / "py.out"), "ok " + std::to_string(4 + gridFits()) + "\n");
}

// Without rsvg-convert on PATH: the SVGs and CSVs all the same, "png": null, and one line saying why.
TEST(PlotCli, WithoutRsvgConvertWritesSvgAndSaysSo) {
  TempDir tmp;
  const auto material = withoutMeasured(tmp, "chrome");
  const RunResult r = runGlossyIn(tmp.path(), {"PATH", "GLOSSY_MERL_DIR"},
                                  {"plot", "--material", material.string(), "--figures", "albedo,polar", "-o", (tmp / "out").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("PNGs need librsvg2-bin"), std::string::npos) << r.err;
  const nlohmann::json index = readIndex(tmp / "out");
  ASSERT_EQ(index["figures"].size(), 2u);
  for (const auto& f : index["figures"]) {
    EXPECT_TRUE(f["png"].is_null());
    EXPECT_TRUE(std::filesystem::exists(tmp / "out" / std::string(f["svg"])));
  }
  EXPECT_FALSE(std::filesystem::exists(tmp / "out/albedo.png"));
}

// --panels: exactly the BRDFs named, in that order, glossy's fits beside the grid included; the legend and
// the CSV columns follow it.
TEST(PlotCli, PanelsChooseTheCurvesAndTheirOrder) {
  TempDir tmp;
  const std::string material = (materialsDir() / "chrome.toml").string();
  const RunResult r = runGlossyIn(tmp.path(), {"GLOSSY_MERL_DIR"},
                                  {"plot", "--material", material, "--panels", "ggx:E2:glossy,measured,cook-torrance:E1",
                                   "--figures", "theta_h,image_slice", "-o", (tmp / "out").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const nlohmann::json index = readIndex(tmp / "out");
  std::vector<std::string> slices;
  for (const auto& f : index["figures"]) {
    if (f["kind"] == "image_slice") slices.push_back(f["title"]);
    if (f["kind"] != "theta_h") continue;
    const std::string text = readText(tmp / "out" / std::string(f["csv"]));
    std::vector<std::string> brdfs;  // the header's BRDF columns, in order
    std::istringstream header(text.substr(0, text.find('\n')));
    for (std::string column; std::getline(header, column, ',');)
      if (column == "Measured" || column.find(" E") != std::string::npos) brdfs.push_back(column);
    EXPECT_EQ(brdfs, (std::vector<std::string>{"GGX E2 (glossy fit)", "Measured", "CT E1"})) << f["csv"];
  }
  ASSERT_EQ(slices.size(), 3u);  // one per BRDF named
  EXPECT_NE(slices[0].find("GGX E2"), std::string::npos) << slices[0];
  EXPECT_NE(slices[2].find("CT E1"), std::string::npos) << slices[2];
}

TEST(PlotCli, BadInputExitsTwoWithOneLine) {
  TempDir tmp;
  const std::string material = (materialsDir() / "chrome.toml").string();
  expectOneLineError(runGlossy({"plot", "--material", (tmp / "missing.toml").string(), "-o", (tmp / "out").string()}), "missing.toml");
  expectOneLineError(runGlossy({"plot", "--material", material, "--channel", "X", "-o", (tmp / "out").string()}), "--channel");
  expectOneLineError(runGlossy({"plot", "--material", material, "--figures", "albedo,pie", "-o", (tmp / "out").string()}), "--figures");
  writeText(tmp / "file", "x");
  expectOneLineError(runGlossy({"plot", "--material", material, "-o", (tmp / "file").string()}), "file");
  expectOneLineError(runGlossy({"plot", "--material", material, "--measured", (tmp / "none.binary").string(), "-o", (tmp / "out").string()}),
                     "none.binary");
  expectOneLineError(runGlossy({"plot", "--material", material, "--panels", "measured,phong:E2", "-o", (tmp / "out").string()}), "--panels");
  expectOneLineError(runGlossy({"plot", "--material", material, "--panels", "", "-o", (tmp / "out").string()}), "--panels");
  writeText(tmp / "bad.toml", "name = \"bad\"\n[[fit]]\nmodel = \"cook-torrance\"\n");
  expectOneLineError(runGlossy({"plot", "--material", (tmp / "bad.toml").string(), "-o", (tmp / "out").string()}), "bad.toml");
  EXPECT_FALSE(std::filesystem::exists(tmp / "out"));
}

}  // namespace
}  // namespace glossy::test
