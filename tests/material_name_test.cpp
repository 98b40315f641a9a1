// Material names become file names: the one rule (materials/params/material_name.h), as the loader, the
// importer and glossy sheets apply it.
#include "materials/core/input_error.h"
#include "materials/params/material_file.h"
#include "materials/params/material_name.h"
#include "tests/support/test_support.h"

namespace glossy::test {

TEST(MaterialName, PathsDotsAndControlCharactersAreNotNames) {
  for (const char* good : {"alum-bronze", "gold-metallic-paint2", "a", "Z9", "x_y.z+w", "a..b"})
    EXPECT_TRUE(isMaterialName(good)) << good;
  for (const char* bad : {"", ".", "..", "../../x", "/etc/x", "a/b", ".hidden", "-dash", "_u", "a b", "a\\b", "a\nb", "é"})
    EXPECT_FALSE(isMaterialName(bad)) << bad;
  EXPECT_TRUE(isMaterialName(std::string(kMaxMaterialNameLength, 'a')));
  EXPECT_FALSE(isMaterialName(std::string(kMaxMaterialNameLength + 1, 'a')));
}

TEST(MaterialName, EveryCommittedLibraryNameFitsTheRule) {
  size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(materialsDir()))
    if (e.path().extension() == ".toml") {
      ++files;
      EXPECT_TRUE(isMaterialName(loadMaterialFile(e.path()).name)) << e.path();
    }
  EXPECT_EQ(files, 100u);
}

TEST(MaterialName, LoaderRefusesAPathNamingFileAndLine) {
  for (const char* bad : {"../../x", "/tmp/x", ".", "a/b"}) {
    const std::string message = expectInputError([&] {
      parseMaterialToml("# a material\nname = \"" + std::string(bad) + "\"\n", "evil.toml");
    });
    EXPECT_NE(message.find("evil.toml:2:"), std::string::npos) << message;
    EXPECT_NE(message.find("not a usable material name"), std::string::npos) << message;
  }
}

TEST(MaterialName, ImportAndSheetsRefuseANameThatWouldLeaveTheOutputFolder) {
  TempDir tmp;
  std::filesystem::create_directories(tmp / "lib");
  std::filesystem::create_directories(tmp / "out");
  writeText(tmp / "lib" / "evil.toml", "name = \"../escaped\"\n");
  const RunResult r = runGlossy({"sheets", (tmp / "lib").string(), "-o", (tmp / "out").string(), "--width", "16", "--height",
                                 "16", "--spp", "4"});
  expectOneLineError(r, "evil.toml:1:");
  EXPECT_FALSE(std::filesystem::exists(tmp / "escaped.exr"));
  EXPECT_TRUE(std::filesystem::is_empty(tmp / "out"));

  writeText(tmp / "evil.txt", "Material Name: ../escaped\nCook-Torrance E2 R: K_d = 0.1\n");
  expectOneLineError(runGlossy({"import", (tmp / "evil.txt").string(), "-o", (tmp / "imported").string()}),
                     "not a usable material name");
  EXPECT_FALSE(std::filesystem::exists(tmp / "escaped.toml"));
}

}  // namespace glossy::test
