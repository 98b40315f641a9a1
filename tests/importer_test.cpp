// The importers: the supplement's own text and bbm's .fit lines, their precedence, and their errors.
#include "materials/core/input_error.h"
#include "materials/params/importer.h"
#include "tests/support/test_support.h"

namespace glossy::test {

namespace {

const MaterialFile& byName(const std::vector<MaterialFile>& all, const std::string& name) {
  for (const MaterialFile& m : all)
    if (m.name == name) return m;
  throw std::runtime_error("no material " + name);
}

const Fit& fitOf(const MaterialFile& m, const char* id) {
  const Fit* f = m.find(FitId::parse(id, "test"));
  if (!f) throw std::runtime_error(m.name + " has no " + id);
  return *f;
}

const char* kRow =
    "Cook-Torrance\t$E_1$\tR: $K_d = 0.1063, K_s = 0.058727$ G: $K_d = 0.0816, K_s = 0.043676$ B: $K_d = 0.0557, "
    "K_s = 0.052230$ Common: $m = 0.017044, \\eta = 1.464929$";

}  // namespace

TEST(ImportSupplement, ReadsAllSixMaterialsAndThirtySixFits) {
  GLOSSY_REQUIRE_SHARED("seed/supplement.txt");
  const auto all = importSupplement(readText(sharedDir() / "seed/supplement.txt"), "supplement.txt");
  ASSERT_EQ(all.size(), 6u);
  for (const MaterialFile& m : all) {
    EXPECT_EQ(m.fits.size(), 6u) << m.name;
    EXPECT_EQ(m.measured, m.name + ".binary");
  }
  const Fit& as = fitOf(byName(all, "alum-bronze"), "ashikhmin-shirley:E1");
  EXPECT_EQ(as.params.rgb("kd"), Rgb(0.1062, 0.0815, 0.0556));
  EXPECT_EQ(as.params.rgb("ks"), Rgb(0.248103, 0.184284, 0.220735));
  EXPECT_EQ(as.params.scalar("n"), 6679.521974);
  EXPECT_EQ(as.params.scalar("eta"), 1.453599);
  const Fit& mf = fitOf(byName(all, "chrome"), "microfacet:E2");
  EXPECT_EQ(mf.params.rgb("a"), Rgb(986.846723, 771.035507, 696.134589));
  EXPECT_EQ(mf.params.scalar("b"), 64661.258846);
  EXPECT_EQ(mf.params.scalar("c"), 1.905420);
  EXPECT_EQ(mf.params.scalar("eta"), 99.999413);
  EXPECT_EQ(fitOf(byName(all, "gold-metallic-paint2"), "smooth:E2").params.rgb("kd"), Rgb(0.0));
  EXPECT_EQ(fitOf(byName(all, "gold-paint"), "cook-torrance:E2").params.scalar("m"), 0.206591);  // under a ### heading
}

TEST(ImportSupplement, RowErrorsNameFileLineAndProblem) {
  const std::string head = "## 2 Material Name: test\n\nModel\tFitting Metric\tModel Parameters\n";
  EXPECT_EQ(importSupplement(head + kRow + "\n", "s.txt").at(0).fits.size(), 1u);
  std::string e = expectInputError([&] { importSupplement(head + std::string(kRow).replace(std::string(kRow).find("Common"), 6, "Shared") + "\n", "s.txt"); });
  EXPECT_NE(e.find("s.txt:4: test cook-torrance:E1: expected the groups"), std::string::npos) << e;
  e = expectInputError([&] { importSupplement(head + std::string(kRow).replace(std::string(kRow).find("m = 0.017044"), 12, "m = -0.017") + "\n", "s.txt"); });
  EXPECT_NE(e.find("s.txt:4"), std::string::npos) << e;
  EXPECT_NE(e.find("'m'"), std::string::npos) << e;
  e = expectInputError([&] { importSupplement(head + std::string(kRow).replace(std::string(kRow).find("K_s = 0.043676"), 14, "Q = 0.043676") + "\n", "s.txt"); });
  EXPECT_NE(e.find("unknown parameter 'Q'"), std::string::npos) << e;
  e = expectInputError([&] { importSupplement(std::string(kRow) + "\n", "s.txt"); });
  EXPECT_NE(e.find("s.txt:1: parameter row before any 'Material Name:'"), std::string::npos) << e;
  e = expectInputError([&] { importSupplement(head + kRow + "\n" + kRow + "\n", "s.txt"); });
  EXPECT_NE(e.find("s.txt:5"), std::string::npos) << e;
  EXPECT_NE(e.find("second cook-torrance:E1"), std::string::npos) << e;
  e = expectInputError([&] { importSupplement(head, "s.txt"); });
  EXPECT_NE(e.find("material 'test' has no parameter rows"), std::string::npos) << e;
}

TEST(ImportFitLines, ReadsEveryPublishedFile) {
  GLOSSY_REQUIRE_SHARED("fits");
  struct Expect {
    const char* file;
    const char* id;
  };
  for (const Expect& x : {Expect{"low_ashikhminshirley_E1.fit", "ashikhmin-shirley:E1"}, Expect{"low_ashikhminshirley_E2.fit", "ashikhmin-shirley:E2"},
                          Expect{"low_cooktorrance_E1.fit", "cook-torrance:E1"}, Expect{"low_cooktorrance_E2.fit", "cook-torrance:E2"},
                          Expect{"low_lowmicrofacet_E2.fit", "microfacet:E2"}, Expect{"low_lowsmooth_E2.fit", "smooth:E2"}}) {
    const auto path = sharedDir() / "fits" / x.file;
    const auto all = importFitLines(readText(path), path.string());
    EXPECT_EQ(all.size(), 100u) << x.file;
    for (const MaterialFile& m : all) {
      ASSERT_EQ(m.fits.size(), 1u);
      EXPECT_EQ(m.fits[0].id.str(), x.id) << x.file;
    }
  }
  const auto as = importFitLines(readText(sharedDir() / "fits/low_ashikhminshirley_E1.fit"), "low_ashikhminshirley_E1.fit");
  const Fit& f = byName(as, "alum-bronze").fits[0];
  EXPECT_EQ(f.params.rgb("ks"), Rgb(0.2481, 0.18428, 0.22073));
  EXPECT_EQ(f.params.scalar("n"), 6679.521974);
  EXPECT_EQ(f.params.scalar("eta"), 1.45359);  // bbm's "fresnelReflectance" holds η
}

TEST(ImportFitLines, MetricComesFromTheFileNameOrTheHeaderComment) {
  const std::string line =
      "x = Aggregate(Lambertian(albedo = [0.1, 0.2, 0.3]), LowCookTorrance(albedo = [0.01, 0.02, 0.03], roughness = 0.1, eta = 1.5))\n";
  EXPECT_EQ(importFitLines(line, "dir/low_cooktorrance_E2.fit").at(0).fits[0].id.str(), "cook-torrance:E2");
  EXPECT_EQ(importFitLines("# the E1 fits of the model\n" + line, "ct.fit").at(0).fits[0].id.str(), "cook-torrance:E1");
  EXPECT_NE(expectInputError([&] { importFitLines(line, "ct.fit"); }).find("ct.fit: cannot tell the metric"), std::string::npos);
}

TEST(ImportFitLines, LineErrorsNameFileAndLine) {
  const std::string ok =
      "a = Aggregate(Lambertian(albedo = [0.1, 0.2, 0.3]), LowSmooth(A = [1, 2, 3], B = 10, C = 0.5, eta = 1.5))\n";
  std::string e = expectInputError([&] { importFitLines(ok + "b = Aggregate(Lambertian(albedo = [0.1, 0.2, 0.3]), Phong(n = 3))\n", "f_E2.fit"); });
  EXPECT_NE(e.find("f_E2.fit:2: unknown model 'Phong'"), std::string::npos) << e;
  e = expectInputError([&] { importFitLines(ok + "garbage\n", "f_E2.fit"); });
  EXPECT_NE(e.find("f_E2.fit:2: not a fit line"), std::string::npos) << e;
  e = expectInputError([&] { importFitLines("a = Aggregate(Lambertian(albedo = [0.1, 0.2]), LowSmooth(A = [1, 2, 3], B = 10, C = 0.5, eta = 1.5))\n", "f_E2.fit"); });
  EXPECT_NE(e.find("f_E2.fit:1"), std::string::npos) << e;
  EXPECT_NE(e.find("expected 3 values"), std::string::npos) << e;
  e = expectInputError([&] { importFitLines("a = Aggregate(Lambertian(albedo = [0.1, 0.2, 0.3]), LowSmooth(A = [1, 2, 3], B = 10, C = 0, eta = 1.5))\n", "f_E2.fit"); });
  EXPECT_NE(e.find("'c'"), std::string::npos) << e;
  e = expectInputError([&] { importFitLines("a = Aggregate(Lambertian(albedo = [0.1, 0.2, 0.3]), LowSmooth(A = [1, 2, 3], B = 10, D = 3, C = 1, eta = 1.5))\n", "f_E2.fit"); });
  EXPECT_NE(e.find("unknown argument 'D'"), std::string::npos) << e;
  e = expectInputError([&] { importFitLines("a = Aggregate(Lambertian(albedo = [0.1, 0.2, 0.3]), LowSmooth(A = [1, 2, 3], B = 10, eta = 1.5))\n", "f_E2.fit"); });
  EXPECT_NE(e.find("missing key 'c'"), std::string::npos) << e;
  e = expectInputError([&] { importFitLines(ok + ok, "f_E2.fit"); });
  EXPECT_NE(e.find("f_E2.fit:2: material 'a' appears twice"), std::string::npos) << e;
}

// Ngan et al.'s fits are of MERL tables read without their green and blue factors: their albedos are held
// times (1, 1.15, 1.66) (docs/materials.md), the rest as published, and the source says so. A scalar albedo is
// bad input (exit 2), not a failure of the conversion.
TEST(ImportFitLines, NganFitsAlbedosTakeMerlsChannelFactors) {
  const auto all = importFitLines(
      "teflon = Aggregate(Lambertian(albedo = [0.296, 0.255, 0.174]), NganWard(albedo = [0.0436, 0.0382, 0.0268], roughness = 0.158))\n",
      "ngan_ward.fit");
  const Fit& f = all.at(0).fits.at(0);
  EXPECT_EQ(f.id.str(), "ward:Ngan05");
  EXPECT_EQ(f.params.rgb("kd"), Rgb(0.296, 0.29325, 0.28884));
  EXPECT_EQ(f.params.rgb("ks"), Rgb(0.0436, 0.04393, 0.044488));
  EXPECT_EQ(f.params.scalar("alpha"), 0.158);
  EXPECT_NE(f.source.find("kd and ks times (1, 1.15, 1.66)"), std::string::npos) << f.source;
  // Bagher et al.'s were fitted to the data as glossy reads it: as published.
  const auto sgd = importFitLines(readText(sourceDir() / "materials/published-fits/bagher_sgd.fit"), "bagher_sgd.fit");
  EXPECT_EQ(byName(sgd, "teflon").fits[0].source.find("times"), std::string::npos);
  const std::string e = expectInputError([&] {
    importFitLines("t = Aggregate(Lambertian(albedo = [0.1, 0.1, 0.1]), NganWard(albedo = 0.5, roughness = 0.1))\n", "ngan_ward.fit");
  });
  EXPECT_NE(e.find("ngan_ward.fit:1: t ward:Ngan05: key 'ks': must be an array of 3 numbers"), std::string::npos) << e;
}

TEST(Importer, SupplementBeatsFitLinesWhateverTheOrderAndOtherFitsAreKept) {
  GLOSSY_REQUIRE_SHARED("seed/supplement.txt");
  GLOSSY_REQUIRE_SHARED("fits");
  for (bool supplementFirst : {true, false}) {
    Importer imp;
    if (supplementFirst) imp.addFile(sharedDir() / "seed/supplement.txt");
    imp.addFile(sharedDir() / "fits/low_ashikhminshirley_E1.fit");
    if (!supplementFirst) imp.addFile(sharedDir() / "seed/supplement.txt");
    // An existing file with a fit the sources don't give, and a copy of one they do (to bbm's rounding).
    MaterialFile existing;
    existing.name = "alum-bronze";
    existing.measured = "alum-bronze.binary";
    existing.source = "my lab";
    Fit mine;
    mine.id = {"lambertian", "E1"};
    mine.params.set("kd", Rgb(0.5));
    existing.put(mine);
    Fit stale;
    stale.id = {"ashikhmin-shirley", "E1"};
    stale.params = fitOf(byName(importSupplement(readText(sharedDir() / "seed/supplement.txt"), "s"), "alum-bronze"), "ashikhmin-shirley:E1").params;
    stale.params.set("n", 6679.52);
    existing.put(stale);

    const MaterialFile m = imp.mergeInto(existing, "alum-bronze");
    EXPECT_EQ(fitOf(m, "ashikhmin-shirley:E1").params.rgb("ks"), Rgb(0.248103, 0.184284, 0.220735)) << supplementFirst;
    EXPECT_EQ(fitOf(m, "ashikhmin-shirley:E1").params.scalar("n"), 6679.521974);
    EXPECT_NE(m.find(mine.id), nullptr) << "a fit the sources don't give is kept";
    EXPECT_EQ(m.fits.size(), 7u);
    EXPECT_EQ(m.source, std::string(kSupplementSource));
    EXPECT_EQ(fitOf(m, "lambertian:E1").source, "my lab") << "the differing provenance stays on the fit";
    // Materials only the .fit file has keep bbm's values.
    EXPECT_EQ(fitOf(imp.mergeInto({}, "aluminium"), "ashikhmin-shirley:E1").params.scalar("n"), 292101.373392);
  }
}

// A published fit is never replaced: values that contradict one already in the file, or one an earlier
// source gave, are refused naming the file and the fit (a crafted .fit cannot pass for the paper's).
TEST(Importer, NeverReplacesAPublishedFit) {
  GLOSSY_REQUIRE_SHARED("fits/low_ashikhminshirley_E1.fit");
  TempDir tmp;
  const std::string real = readText(sharedDir() / "fits/low_ashikhminshirley_E1.fit");
  const size_t at = real.find("alum-bronze");
  ASSERT_NE(at, std::string::npos);
  std::string line = real.substr(at, real.find('\n', at) - at);
  const size_t n = line.find("sharpness = ");
  ASSERT_NE(n, std::string::npos) << line;
  line.replace(n, line.find_first_of(",)", n) - n, "sharpness = 12.5");
  std::filesystem::create_directories(tmp / "crafted");
  writeText(tmp / "crafted/low_ashikhminshirley_E1.fit", line + "\n");

  // Against the file a genuine import wrote.
  ASSERT_EQ(runGlossy({"import", (sharedDir() / "fits/low_ashikhminshirley_E1.fit").string(), "-o", (tmp / "out").string()}).status, 0);
  const std::string before = readText(tmp / "out/alum-bronze.toml");
  for (const char* flag : {"", "--replace"}) {
    SCOPED_TRACE(flag);
    std::vector<std::string> args{"import", (tmp / "crafted/low_ashikhminshirley_E1.fit").string(), "-o", (tmp / "out").string()};
    if (*flag) args.push_back(flag);
    const RunResult r = runGlossy(args);
    expectOneLineError(r, "alum-bronze.toml");
    expectOneLineError(r, "ashikhmin-shirley:E1");
    EXPECT_EQ(readText(tmp / "out/alum-bronze.toml"), before);
  }
  // Against an earlier source in the same import.
  const RunResult r = runGlossy({"import", (sharedDir() / "fits/low_ashikhminshirley_E1.fit").string(),
                                 (tmp / "crafted/low_ashikhminshirley_E1.fit").string(), "-o", (tmp / "fresh").string()});
  expectOneLineError(r, "crafted/low_ashikhminshirley_E1.fit");
  EXPECT_FALSE(std::filesystem::exists(tmp / "fresh/alum-bronze.toml"));
  // The same fits again change nothing.
  ASSERT_EQ(runGlossy({"import", (sharedDir() / "fits/low_ashikhminshirley_E1.fit").string(), "-o", (tmp / "out").string()}).status, 0);
  EXPECT_EQ(readText(tmp / "out/alum-bronze.toml"), before);
}

TEST(Importer, RejectsFilesOfNeitherKind) {
  TempDir tmp;
  writeText(tmp / "notes.txt", "nothing to see\n");
  Importer imp;
  EXPECT_NE(expectInputError([&] { imp.addFile(tmp / "notes.txt"); }).find("notes.txt: neither"), std::string::npos);
  EXPECT_NE(expectInputError([&] { imp.addFile(tmp / "absent.fit"); }).find("absent.fit: cannot open"), std::string::npos);
}

}  // namespace glossy::test
