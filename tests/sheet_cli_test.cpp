// glossy sheet and glossy sheets through the command line: the layered EXR (grid + 7 panels) and the PNG,
// the error table and metadata, labelled empty panels, the smooth fit's Fresnel angle, --time,
// --target-error, batch resuming and sharding, bad input.
#include "renderer/image/colour_maps.h"
#include "renderer/image/delta_e_itp.h"
#include "renderer/image/exr_image.h"
#include "renderer/image/masked_mean.h"
#include "renderer/image/ssim.h"
#include "renderer/sheet/error_maps.h"
#include "renderer/sheet/sheet.h"
#include "materials/params/material_file.h"
#include "tests/support/test_support.h"

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include <cmath>

namespace glossy::test {

namespace {

std::vector<std::string> tiny(std::vector<std::string> args) {
  for (const char* a : {"--width", "16", "--height", "16", "--spp", "2"}) args.push_back(a);
  return args;
}

std::vector<std::string> channelsOf(const std::filesystem::path& exr) {
  auto in = OIIO::ImageInput::open(exr.string());
  if (!in) return {};
  return in->spec().channelnames;
}

}  // namespace

TEST(CliSheet, EverySupplementMaterialGivesTheLayeredExrAndThePngWithNoNonFiniteValue) {
  GLOSSY_REQUIRE_SHARED("merl");
  TempDir tmp;
  for (const std::string& name : supplementMaterials()) {
    const std::filesystem::path exr = tmp / (std::string(name) + ".exr");
    const RunResult r = runGlossy(tiny({"sheet", "--material", (materialsDir() / (std::string(name) + ".toml")).string(),
                                        "--measured", (sharedDir() / "merl" / (std::string(name) + ".binary")).string(), "-o",
                                        exr.string()}));
    ASSERT_EQ(r.status, 0) << r.err;
    std::vector<std::string> channels = channelsOf(exr);
    std::sort(channels.begin(), channels.end());
    const std::vector<std::string> want = {
        "B", "G", "R", "ashikhmin_shirley_E1.B", "ashikhmin_shirley_E1.G", "ashikhmin_shirley_E1.R", "ashikhmin_shirley_E2.B",
        "ashikhmin_shirley_E2.G", "ashikhmin_shirley_E2.R", "cook_torrance_E1.B", "cook_torrance_E1.G", "cook_torrance_E1.R",
        "cook_torrance_E2.B", "cook_torrance_E2.G", "cook_torrance_E2.R", "measured.B", "measured.G", "measured.R",
        "microfacet_E2.B", "microfacet_E2.G", "microfacet_E2.R", "smooth_E2.B", "smooth_E2.G", "smooth_E2.R"};
    std::vector<std::string> panels;
    for (const std::string& c : channels)
      if (!c.ends_with("_reldiff.Y") && !c.ends_with("_flip.Y")) panels.push_back(c);
    EXPECT_EQ(panels, want) << name << ": the grid and the 7 panels";
    for (const char* layer : {"microfacet_E2", "smooth_E2", "ashikhmin_shirley_E1", "ashikhmin_shirley_E2", "cook_torrance_E1", "cook_torrance_E2"})
      for (const char* map : {"_reldiff.Y", "_flip.Y"})
        EXPECT_NE(std::find(channels.begin(), channels.end(), layer + std::string(map)), channels.end()) << name << ": " << layer << map;
    EXPECT_EQ(channels.size(), want.size() + 12) << name << ": two error maps per model panel";
    const RgbImage grid = readRgbImage(exr);
    EXPECT_EQ(grid.width, 7 * 16);
    EXPECT_EQ(grid.height, 16);
    for (float v : grid.pixels) ASSERT_TRUE(std::isfinite(v)) << name;
    // The measured layer holds the measured panel at its place in the grid, and nothing else.
    const RgbImage measured = readImageLayer(exr, "measured");
    EXPECT_EQ(measured.at(5, 5)[1], grid.at(5, 5)[1]);
    EXPECT_EQ(measured.at(16 + 5, 5)[1], 0.0f);
    EXPECT_EQ(readImageAttribute(exr, "glossy:panel.smooth_E2.box"), "32 0 16 16");
    EXPECT_FALSE(readImageAttribute(exr, "glossy:error.cook_torrance_E2.relativeRmse").empty()) << name;
    // The BRDF-space errors are glossy error's, for every fit panel.
    if (name == supplementMaterials().front()) {
      const RunResult e = runGlossy({"error", "--material", (materialsDir() / (std::string(name) + ".toml")).string(), "--measured",
                                     (sharedDir() / "merl" / (std::string(name) + ".binary")).string(), "--json"});
      ASSERT_EQ(e.status, 0) << e.err;
      const auto json = nlohmann::json::parse(e.out);
      ASSERT_EQ(json["fits"].size(), loadMaterialFile(materialsDir() / (std::string(name) + ".toml")).fits.size());
      for (const auto& f : json["fits"]) {
        // The grid's panels only (glossy's refits and the fits of models outside the grid are not panels).
        const std::string id = f["fit"].get<std::string>();
        if (std::none_of(sheetPanels().begin(), sheetPanels().end(), [&](const SheetPanel& p) { return p.fit == id; })) continue;
        std::string layer = f["fit"].get<std::string>();
        std::replace(layer.begin(), layer.end(), '-', '_');
        std::replace(layer.begin(), layer.end(), ':', '_');
        for (const char* metric : {"E1", "E2"}) {
          const std::string key = "glossy:error." + layer + "." + metric;
          ASSERT_FALSE(readImageAttribute(exr, key).empty()) << key;
          EXPECT_NEAR(std::stod(readImageAttribute(exr, key)), f[metric].get<double>(), 1e-5 * f[metric].get<double>()) << key;  // stored as float, read as 6 digits
        }
      }
      EXPECT_NE(r.out.find("BRDF E2"), std::string::npos) << r.out;
    }
    EXPECT_NE(readImageAttribute(exr, "glossy:measured").find("NBRDF reconstruction"), std::string::npos);
    const RgbImage png = readRgbImage(tmp / (std::string(name) + ".png"));
    EXPECT_EQ(png.width, 7 * 16);
    EXPECT_GT(png.height, 16) << "a label strip under the panels";
    // 2 spp are 2 replicates: a noise-free figure, but no interval and so no verdict, said so.
    EXPECT_NE(r.out.find("no verdict: fewer than 4 replicates"), std::string::npos) << r.out;
    EXPECT_EQ(readImageAttribute(exr, "glossy:verdict"), "no verdict: fewer than 4 replicates");
    EXPECT_TRUE(readImageAttribute(exr, "glossy:error.cook_torrance_E2.relativeRmseCi").empty());
    EXPECT_NE(r.out.find("CT E2"), std::string::npos) << r.out;
  }
}

// The error maps: the EXR's relative-difference layer is the formula of error_maps.h applied to the EXR's own
// panel layers, and the PNG's second row shows it in the diverging colours; the ꟻLIP figures and their map
// hang together, and the parameters are the file's.
TEST(CliSheet, ErrorMapsAreTheRelativeDifferenceOfThePanelsShownInThePngsSecondRow) {
  GLOSSY_REQUIRE_SHARED("merl");
  TempDir tmp;
  const std::filesystem::path exr = tmp / "alum-bronze.exr";
  const RunResult r = runGlossy({"sheet", "--material", (materialsDir() / "alum-bronze.toml").string(), "--merl-dir",
                                 (sharedDir() / "merl").string(), "--width", "32", "--height", "32", "--spp", "16", "-o", exr.string()});
  ASSERT_EQ(r.status, 0) << r.err;
  auto in = OIIO::ImageInput::open(exr.string());
  ASSERT_TRUE(in);
  const OIIO::ImageSpec spec = in->spec();
  const auto channel = [&](const std::string& name) {
    const int c = spec.channelindex(name);
    std::vector<float> v(size_t(spec.width) * size_t(spec.height));
    EXPECT_GE(c, 0) << name;
    if (c >= 0) {
      EXPECT_TRUE(in->read_image(0, 0, c, c + 1, OIIO::TypeDesc::FLOAT, v.data()));
    }
    return v;
  };
  const int w = 32, h = 32, x0 = 4 * w;  // AS E2, the fifth panel
  ASSERT_EQ(readImageAttribute(exr, "glossy:panel.ashikhmin_shirley_E2.box"), "128 0 32 32");
  const std::vector<float> d = channel("ashikhmin_shirley_E2_reldiff.Y"), flip = channel("ashikhmin_shirley_E2_flip.Y");
  const RgbImage m = readImageLayer(exr, "measured"), p = readImageLayer(exr, "ashikhmin_shirley_E2");
  const auto lum = [](const float* c) { return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]; };
  // The object: where the map is not 0 (an exact 0 on the object is vanishingly rare in a noisy render).
  double sum = 0.0, flipSum = 0.0;
  size_t object = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (d[size_t(y) * spec.width + x0 + x] != 0.0f) sum += lum(m.at(x, y)), flipSum += flip[size_t(y) * spec.width + x0 + x], ++object;
  ASSERT_GT(object, size_t(w * h / 10)) << "the object covers the panel's middle";
  const double lumFloor = 0.01 * sum / double(object);
  const RgbImage png = readRgbImage(tmp / "alum-bronze.png");
  ASSERT_EQ(png.width, 7 * w);
  ASSERT_GT(png.height, 2 * h) << "the panels, their labels, and the row of maps";
  ASSERT_EQ(png.height, sheetPngSize(w, h, 7).heightWithMaps);
  const int mapTop = sheetPngSize(w, h, 7).height;  // the maps' row, under the labels and above the note strip
  size_t checked = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const float v = d[size_t(y) * spec.width + x0 + x];
      EXPECT_EQ(d[size_t(y) * spec.width + x], 0.0f) << "nothing under the measured panel";
      if (v == 0.0f) continue;
      const double ym = lum(m.at(x, y)), yp = lum(p.at(x0 + x, y));
      EXPECT_NEAR(v, (yp - ym) / std::max(ym, lumFloor), 1e-4 * std::max(1.0, std::abs(double(v)))) << x << "," << y;
      const DisplayColour c = divergingColour(v / kRelativeDifferenceRange);
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(png.at(x0 + x, mapTop + y)[k], c[size_t(k)], 1.5 / 255.0) << x << "," << y;
      ++checked;
    }
  EXPECT_EQ(checked, object);
  // ꟻLIP: the figure is the map's mean over the object, inside its interval; the noise floor is below it.
  const double flipFigure = std::stod(readImageAttribute(exr, "glossy:error.ashikhmin_shirley_E2.flip"));
  EXPECT_NEAR(flipSum / double(object), flipFigure, 1e-5);
  EXPECT_GT(flipFigure, 0.0);
  double lo = 0.0, hi = 0.0;
  ASSERT_EQ(std::sscanf(readImageAttribute(exr, "glossy:error.ashikhmin_shirley_E2.flipCi").c_str(), "%lf %lf", &lo, &hi), 2);
  EXPECT_LE(lo, flipFigure);
  EXPECT_GE(hi, flipFigure);
  const double floor = std::stod(readImageAttribute(exr, "glossy:flipNoiseFloor"));
  EXPECT_GT(floor, 0.0);
  EXPECT_LT(floor, flipFigure) << "AS E2 differs from the measured panel by more than 16 spp of noise";
  EXPECT_NE(r.out.find("HDR-FLIP"), std::string::npos) << r.out;
  // ΔE_ITP and SSIM of the panels as shown: recomputed from the EXR's own layers over the object, inside their
  // intervals; noise alone (the noise-floor row) is nearer the measured panel than AS E2 is.
  std::vector<char> mask(size_t(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) mask[size_t(y) * w + x] = d[size_t(y) * spec.width + x0 + x] != 0.0f;
  RgbImage mPanel(w, h), pPanel(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int k = 0; k < 3; ++k) mPanel.at(x, y)[k] = m.at(x, y)[k], pPanel.at(x, y)[k] = p.at(x0 + x, y)[k];
  const std::string key = "glossy:error.ashikhmin_shirley_E2.";
  const double deltaE = std::stod(readImageAttribute(exr, key + "deltaEItp")), ssim = std::stod(readImageAttribute(exr, key + "ssim"));
  EXPECT_NEAR(maskedMean(deltaEItpMap(mPanel, pPanel), mask), deltaE, 1e-4 * deltaE);
  EXPECT_NEAR(maskedMean(ssimMap(mPanel, pPanel), mask), ssim, 1e-5);
  for (const auto& [name, value] : {std::pair{"deltaEItpCi", deltaE}, std::pair{"ssimCi", ssim}}) {
    ASSERT_EQ(std::sscanf(readImageAttribute(exr, key + name).c_str(), "%lf %lf", &lo, &hi), 2) << name;
    EXPECT_LE(lo, value) << name;
    EXPECT_GE(hi, value) << name;
  }
  EXPECT_LT(std::stod(readImageAttribute(exr, "glossy:noiseFloor.deltaEItp")), deltaE);
  EXPECT_GT(std::stod(readImageAttribute(exr, "glossy:noiseFloor.ssim")), ssim);
  EXPECT_NE(r.out.find("dE_ITP"), std::string::npos) << r.out;
  EXPECT_EQ(readImageAttribute(exr, "glossy:panel.ashikhmin_shirley_E1.params"),
            "kd = [0.1062, 0.0815, 0.0556]; ks = [0.248103, 0.184284, 0.220735]; n = 6679.521974; eta = 1.453599");
  EXPECT_EQ(readImageAttribute(exr, "glossy:panel.measured.params"), "");
}

TEST(CliSheet, MissingMeasuredDataAndMissingFitsGiveLabelledEmptyPanels) {
  TempDir tmp;
  // Two fits only, and a measured table nobody has.
  writeText(tmp / "two.toml", R"(name = "two"
measured = "nowhere-to-be-found.binary"

[[fit]]
model = "cook-torrance"
metric = "E2"
kd = [0.1, 0.1, 0.1]
ks = [0.2, 0.2, 0.2]
m = 0.2
eta = 1.5

[[fit]]
model = "smooth"
metric = "E2"
kd = [0.1, 0.1, 0.1]
a = [2.0, 2.0, 2.0]
b = 100.0
c = 1.5
eta = 1.5
)");
  const RunResult r = runGlossy(tiny({"sheet", "--material", (tmp / "two.toml").string(), "--merl-dir", tmp.path().string(), "-o",
                                      (tmp / "two.exr").string()}));
  ASSERT_EQ(r.status, 0) << r.err;
  const auto attr = [&](const std::string& key) { return readImageAttribute(tmp / "two.exr", key); };
  EXPECT_EQ(attr("glossy:panel.measured.empty"), "1");
  EXPECT_NE(attr("glossy:panel.measured.note").find("MERL"), std::string::npos) << "says where to get MERL data";
  EXPECT_EQ(attr("glossy:panel.microfacet_E2.empty"), "1");
  EXPECT_NE(attr("glossy:panel.microfacet_E2.note").find("no microfacet:E2 fit"), std::string::npos);
  EXPECT_EQ(attr("glossy:panel.cook_torrance_E2.empty"), "0");
  EXPECT_EQ(attr("glossy:errors"), "none: no measured panel");
  EXPECT_EQ(attr("glossy:smoothFresnel"), "projected") << "the smooth fit's default";
  EXPECT_TRUE(attr("glossy:error.cook_torrance_E2.relativeRmse").empty());
  EXPECT_NE(r.out.find("no measured panel"), std::string::npos) << r.out;
  EXPECT_EQ(readImageLayer(tmp / "two.exr", "microfacet_E2").at(16 + 3, 3)[0], 0.0f);
  EXPECT_TRUE(std::filesystem::exists(tmp / "two.png"));
}

// scripts/run's command on a clone with nothing beside it: no ../shared, no $GLOSSY_MERL_DIR or
// $GLOSSY_SHARED_DIR. The measured panel comes from the network embedded beside the material file, the sheet
// says so, and every model gets its figures.
TEST(CliSheet, AFreshCloneAloneRendersAllSevenPanelsFromTheEmbeddedNetwork) {
  TempDir tmp;
  const std::filesystem::path clone = tmp / "glossy";
  std::filesystem::create_directories(clone / "materials/library/merl");
  for (const char* file : {"alum-bronze.toml", "alum-bronze.nbrdf"})
    std::filesystem::copy_file(materialsDir() / file, clone / "materials/library/merl" / file);
  ASSERT_FALSE(std::filesystem::exists(tmp / "shared"));
  const std::vector<std::string> unset = {"GLOSSY_MERL_DIR", "GLOSSY_SHARED_DIR"};
  const std::vector<std::string> args = {"sheet", "--material", "materials/library/merl/alum-bronze.toml", "-o", "out/alum-bronze.exr",
                                         "--width", "16", "--height", "16", "--spp", "8"};
  const RunResult r = runGlossyIn(clone, unset, args);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("MERL (NBRDF reconstruction) materials/library/merl/alum-bronze.nbrdf"), std::string::npos) << r.out;
  EXPECT_TRUE(r.out.find("closest: ") != std::string::npos || r.out.find("tie: ") != std::string::npos) << r.out;
  const std::filesystem::path exr = clone / "out/alum-bronze.exr";
  const auto attr = [&](const std::string& key) { return readImageAttribute(exr, key); };
  EXPECT_EQ(attr("glossy:measured"), "MERL (NBRDF reconstruction) materials/library/merl/alum-bronze.nbrdf");
  for (const char* layer : {"measured", "microfacet_E2", "smooth_E2", "ashikhmin_shirley_E1", "ashikhmin_shirley_E2",
                            "cook_torrance_E1", "cook_torrance_E2"}) {
    EXPECT_EQ(attr("glossy:panel." + std::string(layer) + ".empty"), "0") << layer;
    if (std::string(layer) != "measured") {
      EXPECT_FALSE(attr("glossy:error." + std::string(layer) + ".relativeRmse").empty()) << layer;
      EXPECT_NE(r.out.find(attr("glossy:panel." + std::string(layer) + ".label")), std::string::npos) << layer;
    }
  }
  double sum = 0.0;
  for (float v : readImageLayer(exr, "measured").pixels) sum += v;
  EXPECT_GT(sum, 0.0);
  EXPECT_TRUE(std::filesystem::exists(clone / "out/alum-bronze.png"));

  // glossy list tells a table from a network; without the network the panel is empty and says why.
  const RunResult list = runGlossyIn(clone, unset, {"list", "materials/library/merl/alum-bronze.toml"});
  ASSERT_EQ(list.status, 0) << list.err;
  EXPECT_NE(list.out.find("network"), std::string::npos) << list.out;
  std::filesystem::remove(clone / "materials/library/merl/alum-bronze.nbrdf");
  const RunResult bare = runGlossyIn(clone, unset, args);
  ASSERT_EQ(bare.status, 0) << bare.err;
  EXPECT_EQ(attr("glossy:panel.measured.empty"), "1");
  EXPECT_NE(bare.out.find("no measured panel"), std::string::npos) << bare.out;
}

// A network names its database wherever the sheet names its measured data: the error table,
// glossy:measured and the measured panel's caption in the PNG. The same network labelled MERL gives the same
// sheet but for that caption.
TEST(CliSheet, ANetworkFromRglEpflNamesThatDatabase) {
  const std::filesystem::path spectralon = libraryDir() / "rgl-epfl/spectralon.nbrdf";
  ASSERT_TRUE(std::filesystem::exists(spectralon)) << spectralon;
  TempDir tmp;
  const std::string merl = readText(materialsDir() / "chrome.toml");
  const size_t first = merl.find("[[fit]]");
  const std::string oneFit = merl.substr(first, merl.find("\n[[fit]]", first) - first);
  const std::string label = "label = \"RGL-EPFL (NBRDF reconstruction)\"";
  std::string relabelled = readText(spectralon);
  ASSERT_NE(relabelled.find(label), std::string::npos);
  relabelled.replace(relabelled.find(label), label.size(), "label = \"MERL (NBRDF reconstruction)\"");
  writeText(tmp / "merl-labelled.nbrdf", relabelled);
  const auto sheet = [&](const std::string& name, const std::filesystem::path& network) {
    writeText(tmp / (name + ".toml"), "name = \"spectralon\"\nmeasured = \"" + network.string() + "\"\n\n" + oneFit);
    return runGlossy({"sheet", "--material", (tmp / (name + ".toml")).string(), "--width", "32", "--height", "32",
                      "--spp", "2", "-o", (tmp / (name + ".exr")).string()});
  };
  const RunResult rgl = sheet("rgl", spectralon), relabel = sheet("relabelled", tmp / "merl-labelled.nbrdf");
  ASSERT_EQ(rgl.status, 0) << rgl.err;
  ASSERT_EQ(relabel.status, 0) << relabel.err;
  const std::string named = "RGL-EPFL (NBRDF reconstruction) " + spectralon.string();
  EXPECT_NE(rgl.out.find(named), std::string::npos) << rgl.out;
  EXPECT_EQ(readImageAttribute(tmp / "rgl.exr", "glossy:measured"), named);
  EXPECT_EQ(readImageAttribute(tmp / "rgl.exr", "glossy:panel.measured.note"), named);
  EXPECT_EQ(readImageAttribute(tmp / "relabelled.exr", "glossy:measured"),
            "MERL (NBRDF reconstruction) " + (tmp / "merl-labelled.nbrdf").string());

  // The PNGs differ, and only in the caption under the measured panel (the first of seven).
  const auto png = [](const std::filesystem::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    EXPECT_TRUE(in) << path;
    if (!in) return std::pair{OIIO::ImageSpec(), std::vector<unsigned char>()};
    const OIIO::ImageSpec spec = in->spec();
    std::vector<unsigned char> pixels(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, pixels.data()));
    return std::pair{spec, pixels};
  };
  const auto [spec, a] = png(tmp / "rgl.png");
  const auto [specB, b] = png(tmp / "relabelled.png");
  ASSERT_EQ(spec.width, specB.width);
  ASSERT_EQ(a.size(), b.size());
  const int panel = spec.width / 7;
  size_t differ = 0;
  for (int y = 0; y < spec.height; ++y)
    for (int x = 0; x < spec.width; ++x)
      for (int c = 0; c < spec.nchannels; ++c) {
        const size_t i = (size_t(y) * size_t(spec.width) + size_t(x)) * size_t(spec.nchannels) + size_t(c);
        if (a[i] == b[i]) continue;
        ++differ;
        EXPECT_LT(x, panel) << "(" << x << ", " << y << ") differs outside the measured panel's column";
        EXPECT_GE(y, panel) << "(" << x << ", " << y << ") differs in the panel itself";
      }
  EXPECT_GT(differ, 0u) << "the measured panel's caption names the database";
}

TEST(CliSheet, SmoothFresnelIsWhatTheFileSays) {
  TempDir tmp;
  writeText(tmp / "vh.toml", R"(name = "vh"

[[fit]]
model = "smooth"
metric = "E2"
kd = [0.1, 0.1, 0.1]
a = [2.0, 2.0, 2.0]
b = 100.0
c = 1.5
eta = 1.5
fresnel = "vh"
)");
  const RunResult r = runGlossy(tiny({"sheet", "--material", (tmp / "vh.toml").string(), "-o", (tmp / "vh.exr").string()}));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readImageAttribute(tmp / "vh.exr", "glossy:smoothFresnel"), "vh");
  // glossy render records the fit's choice the same way.
  const RunResult image = runGlossy({"render", "--material", (tmp / "vh.toml").string(), "--fit", "smooth:E2", "--width", "8",
                                     "--height", "8", "--spp", "1", "-o", (tmp / "render.exr").string()});
  ASSERT_EQ(image.status, 0) << image.err;
  EXPECT_EQ(readImageAttribute(tmp / "render.exr", "glossy:smoothFresnel"), "vh");
}

TEST(CliSheet, TimeBudgetRendersProgressively) {
  TempDir tmp;
  const RunResult r = runGlossy({"sheet", "--material", (materialsDir() / "gold-paint.toml").string(), "--merl-dir",
                                 tmp.path().string(), "--width", "16", "--height", "16", "--time", "0.3", "-o",
                                 (tmp / "t.exr").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_GE(std::stoi(readImageAttribute(tmp / "t.exr", "glossy:spp")), 16) << "a 16² panel gets far more than a few samples in 0.3 s";
  EXPECT_GE(std::stoi(readImageAttribute(tmp / "t.exr", "glossy:passes")), 2);
  EXPECT_EQ(readImageAttribute(tmp / "t.exr", "glossy:panel.smooth_E2.spp"), readImageAttribute(tmp / "t.exr", "glossy:spp"));
}

TEST(CliSheet, SppCapsATimeBudget) {
  TempDir tmp;
  const RunResult r = runGlossy({"sheet", "--material", (materialsDir() / "chrome.toml").string(), "--width", "16",
                                 "--height", "16", "--time", "2", "--spp", "24", "-o", (tmp / "t.exr").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readImageAttribute(tmp / "t.exr", "glossy:spp"), "24") << "--spp is the most a --time budget may spend";
}

TEST(CliSheet, TargetErrorRendersUntilEveryIntervalIsThatNarrow) {
  GLOSSY_REQUIRE_SHARED("merl/gold-paint.binary.xz");
  TempDir tmp;
  const double target = 0.01;
  const RunResult r = runGlossy({"sheet", "--material", (materialsDir() / "gold-paint.toml").string(), "--merl-dir",
                                 (sharedDir() / "merl").string(), "--width", "32", "--height", "32", "--target-error", "0.01",
                                 "-o", (tmp / "t.exr").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto attr = [&](const std::string& name) { return readImageAttribute(tmp / "t.exr", name); };
  const int spp = std::stoi(attr("glossy:spp"));
  EXPECT_GT(spp, 16) << "a 32² gold-paint sheet needs more than the first pass for ±0.01";
  EXPECT_GE(std::stoi(attr("glossy:passes")), 2);
  EXPECT_EQ(spp % 4, 0) << "every replicate has as many samples";
  for (const char* layer : {"microfacet_E2", "smooth_E2", "ashikhmin_shirley_E1", "ashikhmin_shirley_E2", "cook_torrance_E1",
                            "cook_torrance_E2"}) {
    double lo = 0.0, hi = 0.0;
    ASSERT_EQ(std::sscanf(attr(std::string("glossy:error.") + layer + ".relativeRmseCi").c_str(), "%lf %lf", &lo, &hi), 2) << layer;
    EXPECT_LE(0.5 * (hi - lo), target * (1 + 1e-6)) << layer;
  }
  EXPECT_FALSE(attr("glossy:verdict").empty());
  EXPECT_EQ(attr("glossy:bsdfSamples"), "1") << "every gold-paint panel is broad";

  // Capped by --spp; without a measured panel there is no interval to aim at: one pass.
  const RunResult capped = runGlossy({"sheet", "--material", (materialsDir() / "gold-paint.toml").string(), "--merl-dir",
                                      (sharedDir() / "merl").string(), "--width", "32", "--height", "32", "--target-error",
                                      "0.0001", "--spp", "32", "-o", (tmp / "c.exr").string()});
  ASSERT_EQ(capped.status, 0) << capped.err;
  EXPECT_EQ(readImageAttribute(tmp / "c.exr", "glossy:spp"), "32");
  // (A copy away from its network, so that no embedded network stands in for the table.)
  std::filesystem::copy_file(materialsDir() / "gold-paint.toml", tmp / "gold-paint.toml");
  const RunResult blind = runGlossy({"sheet", "--material", (tmp / "gold-paint.toml").string(), "--merl-dir",
                                     tmp.path().string(), "--width", "16", "--height", "16", "--target-error", "0.0001", "-o",
                                     (tmp / "b.exr").string()});
  ASSERT_EQ(blind.status, 0) << blind.err;
  EXPECT_EQ(readImageAttribute(tmp / "b.exr", "glossy:passes"), "1");
}

// Where the run chooses the spp, a sheet with a sharp panel takes eight BSDF samples at the object (all
// panels alike); at a fixed --spp one, as it always did.
TEST(CliSheet, ASheetThatChoosesItsSppTakesBsdfSamplesOnSharpPanels) {
  GLOSSY_REQUIRE_SHARED("merl/chrome.binary.xz");
  TempDir tmp;
  const auto sheet = [&](const std::string& name, std::vector<std::string> extra) {
    std::vector<std::string> args = {"sheet", "--material", (materialsDir() / "chrome.toml").string(), "--merl-dir",
                                     (sharedDir() / "merl").string(), "--width", "16", "--height", "16", "-o", (tmp / name).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = runGlossy(args);
    EXPECT_EQ(r.status, 0) << r.err;
    return readImageAttribute(tmp / name, "glossy:bsdfSamples");
  };
  EXPECT_EQ(sheet("target.exr", {"--target-error", "0.05", "--spp", "32"}), "8");
  EXPECT_EQ(sheet("time.exr", {"--time", "0.2", "--spp", "8"}), "8");
  EXPECT_EQ(sheet("fixed.exr", {"--spp", "8"}), "1");
}

TEST(CliSheets, RendersEachMaterialOnceResumesAndShards) {
  TempDir tmp;
  std::filesystem::create_directories(tmp / "lib");
  for (const char* name : {"gold-paint", "blue-rubber", "chrome"})
    std::filesystem::copy_file(materialsDir() / (std::string(name) + ".toml"), tmp / "lib" / (std::string(name) + ".toml"));
  const auto sheets = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = tiny({"sheets", (tmp / "lib").string(), "-o", (tmp / "out").string(), "--merl-dir",
                                          tmp.path().string()});
    args.insert(args.end(), extra.begin(), extra.end());
    return runGlossy(args);
  };
  // Shard 1 of 2 over the sorted files (blue-rubber, chrome, gold-paint): chrome only.
  RunResult r = sheets({"--shard", "1/2"});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(tmp / "out/chrome.exr"));
  EXPECT_FALSE(std::filesystem::exists(tmp / "out/gold-paint.exr"));
  const auto before = std::filesystem::last_write_time(tmp / "out/chrome.exr");
  r = sheets({});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(tmp / "out/blue-rubber.exr"));
  EXPECT_TRUE(std::filesystem::exists(tmp / "out/gold-paint.png"));
  EXPECT_EQ(std::filesystem::last_write_time(tmp / "out/chrome.exr"), before) << "a complete sheet is not rendered again";
  EXPECT_NE(r.err.find("chrome: complete, skipped"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[3/3]"), std::string::npos) << "overall progress";
}

// --panels chooses the panels and their order: two fits and no measured panel give those two layers only,
// labelled from the registry, in the EXR, its metadata and a PNG two panels wide.
TEST(CliSheet, PanelsChooseThePanelsAndTheirOrder) {
  TempDir tmp;
  const RunResult r = runGlossy(tiny({"sheet", "--material", (materialsDir() / "chrome.toml").string(), "--panels",
                                      "microfacet:E2,cook-torrance:E1", "-o", (tmp / "two.exr").string()}));
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<std::string> channels = channelsOf(tmp / "two.exr");
  std::sort(channels.begin(), channels.end());
  EXPECT_EQ(channels, (std::vector<std::string>{"B", "G", "R", "cook_torrance_E1.B", "cook_torrance_E1.G", "cook_torrance_E1.R",
                                                "microfacet_E2.B", "microfacet_E2.G", "microfacet_E2.R"}));
  const auto attr = [&](const std::string& name) { return readImageAttribute(tmp / "two.exr", name); };
  EXPECT_EQ(attr("glossy:panels"), "microfacet_E2,cook_torrance_E1");
  EXPECT_EQ(attr("glossy:panel.microfacet_E2.label"), "Microfacet E2");
  EXPECT_EQ(attr("glossy:panel.cook_torrance_E1.label"), "CT E1");
  EXPECT_EQ(attr("glossy:panel.cook_torrance_E1.box"), "16 0 16 16");
  EXPECT_EQ(attr("glossy:panel.cook_torrance_E1.colour"), "#0072b2");
  EXPECT_NE(attr("glossy:settings").find("; panels=microfacet:E2,cook-torrance:E1;"), std::string::npos) << attr("glossy:settings");
  const auto png = OIIO::ImageInput::open((tmp / "two.png").string());
  ASSERT_TRUE(png);
  EXPECT_EQ(png->spec().width, 32);
  EXPECT_NE(r.out.find("CT E1"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("Smooth E2"), std::string::npos) << r.out;
}

TEST(CliSheet, BadInputExitsTwoWithOneLine) {
  TempDir tmp;
  expectOneLineError(runGlossy({"sheet", "--material", (tmp / "absent.toml").string(), "-o", (tmp / "x.exr").string()}),
                     "absent.toml");
  expectOneLineError(runGlossy({"sheet", "--material", (materialsDir() / "chrome.toml").string(), "--measured",
                                (tmp / "absent.binary").string(), "-o", (tmp / "x.exr").string()}),
                     "absent.binary");
  expectOneLineError(runGlossy({"sheets", (tmp / "nothing").string(), "-o", (tmp / "out").string()}), "nothing");
  expectOneLineError(runGlossy({"sheets", "--shard", "2/2", "-o", (tmp / "out").string()}), "--shard");
  for (const char* option : {"--target-error", "--time"})
    for (const char* bad : {"0", "-0.1", "nan", "inf", "x"})
      expectOneLineError(runGlossy({"sheet", "--material", (materialsDir() / "chrome.toml").string(), option, bad, "-o",
                                    (tmp / "x.exr").string()}),
                         option);
  // Bad --panels stop both commands before any work, naming the option and the value.
  for (const char* command : {"sheet", "sheets"})
    for (const auto& [bad, named] : std::vector<std::pair<std::string, std::string>>{
             {"", "--panels"}, {"bogus:E2", "bogus"}, {"microfacet:E3", "E3"}, {"microfacet", "microfacet"},
             {"measured,measured", "'measured' is named twice"}, {"smooth:E2,microfacet:E1,smooth:E2", "'smooth:E2' is named twice"},
             {"microfacet:E2,,smooth:E2", "empty panel"}, {"microfacet:E2,", "empty panel"}}) {
      const bool one = std::string(command) == "sheet";
      std::vector<std::string> args = {command, (materialsDir() / "chrome.toml").string(), "--panels", bad, "-o",
                                       (tmp / (one ? "x.exr" : "out")).string()};
      if (one) args.insert(args.begin() + 1, "--material");
      const RunResult r = runGlossy(args);
      expectOneLineError(r, "--panels");
      EXPECT_NE(r.err.find(named), std::string::npos) << command << " --panels '" << bad << "': " << r.err;
    }
  EXPECT_FALSE(std::filesystem::exists(tmp / "out"));
  EXPECT_FALSE(std::filesystem::exists(tmp / "x.exr"));
}

// A target too fine to reach stops at the default cap (or --spp), says so on stderr and in the EXR, and
// prints a line per pass though stderr is not a terminal (here a file): a batch log shows how it goes.
TEST(CliSheet, TargetErrorAloneStopsAtItsCapSayingSo) {
  TempDir tmp;
  const std::vector<std::string> base = {"sheet", "--material", (materialsDir() / "chrome.toml").string(), "--width", "8",
                                         "--height", "8", "--target-error", "1e-9"};
  std::vector<std::string> capped = base;
  capped.insert(capped.end(), {"--spp", "16", "-o", (tmp / "c.exr").string()});
  RunResult r = runGlossy(capped);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readImageAttribute(tmp / "c.exr", "glossy:spp"), "16");
  EXPECT_NE(r.err.find("chrome: pass 1: 16 spp, widest interval ±"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("chrome: stopped short of --target-error 1e-09 at 16 spp: the widest interval is ±"), std::string::npos) << r.err;
  EXPECT_GT(std::stod(readImageAttribute(tmp / "c.exr", "glossy:widestInterval")), 1e-9);

  std::vector<std::string> uncapped = base;
  uncapped.insert(uncapped.end(), {"-o", (tmp / "u.exr").string()});
  r = runGlossy(uncapped);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(readImageAttribute(tmp / "u.exr", "glossy:spp"), "4096") << "--target-error alone stops at its default cap";
  EXPECT_NE(r.err.find("stopped short of --target-error 1e-09 at 4096 spp"), std::string::npos) << r.err;
  EXPECT_GE(std::stoi(readImageAttribute(tmp / "u.exr", "glossy:passes")), 3);
}

}  // namespace glossy::test
