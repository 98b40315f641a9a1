// The committed library (materials/library/README.md): a folder per database, each material's name its file's
// stem and unique over the library, each network labelled by its folder's database, each parameter file with
// its network beside it.
#include "materials/nbrdf/neural_brdf.h"
#include "materials/params/material_file.h"
#include "tests/support/test_support.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <optional>
#include <set>

namespace glossy::test {

namespace {

struct Database {
  const char* folder;
  const char* label;
  size_t networks;
};
// The three databases of ../shared/nbrdf/SOURCES.md, as scripts/nbrdf-from-h5 --database labels them.
const Database kDatabases[] = {{"merl", "MERL (NBRDF reconstruction)", 100},
                               {"rgl-epfl", "RGL-EPFL (NBRDF reconstruction)", 51},
                               {"nielsen2015", "Nielsen 2015 (NBRDF reconstruction)", 8}};

// The files of one extension in a database folder (not its subfolders: the library is one level deep).
std::vector<std::filesystem::path> filesIn(const std::filesystem::path& folder, const std::string& extension) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(folder))
    if (e.path().extension() == extension && e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

// $GLOSSY_MERL_DIR unset while alive (restored after), so that only the library's own files resolve.
class NoMerlDir {
 public:
  NoMerlDir() {
    if (const char* v = std::getenv("GLOSSY_MERL_DIR")) saved_ = v;
    unsetenv("GLOSSY_MERL_DIR");
  }
  ~NoMerlDir() {
    if (saved_) setenv("GLOSSY_MERL_DIR", saved_->c_str(), 1);
  }

 private:
  std::optional<std::string> saved_;
};

}  // namespace

TEST(MaterialLibrary, HoldsAFolderPerDatabaseAndNothingElse) {
  std::set<std::string> folders;
  for (const auto& e : std::filesystem::directory_iterator(libraryDir()))
    if (e.is_directory()) folders.insert(e.path().filename().string());
  EXPECT_EQ(folders, (std::set<std::string>{"merl", "nielsen2015", "rgl-epfl"}));
}

// A name becomes NAME.exr among every sheet of the library, and NAME.toml and NAME.nbrdf find each other by
// it: a file's name is its stem, and no name is in two folders (RGL's and Nielsen's cardboard).
TEST(MaterialLibrary, NamesAreTheFileStemsAndUniqueOverTheLibrary) {
  std::map<std::string, std::filesystem::path> folderOf;
  size_t files = 0;
  for (const Database& db : kDatabases) {
    const auto folder = libraryDir() / db.folder;
    ASSERT_TRUE(std::filesystem::is_directory(folder)) << folder;
    for (const char* extension : {".toml", ".nbrdf"})
      for (const auto& file : filesIn(folder, extension)) {
        const std::string name = extension == std::string(".toml") ? loadMaterialFile(file).name : NeuralBrdf::load(file).material();
        EXPECT_EQ(name, file.stem().string()) << file;
        const auto [it, added] = folderOf.emplace(name, folder);
        EXPECT_TRUE(added || it->second == folder) << name << " is in " << it->second << " and " << folder;
        ++files;
      }
  }
  EXPECT_GE(files, 100u + 51u + 8u + 100u);
  EXPECT_EQ(folderOf.size(), 159u) << "a material per network";
}

TEST(MaterialLibrary, EveryNetworkIsLabelledByItsFoldersDatabase) {
  for (const Database& db : kDatabases) {
    const auto folder = libraryDir() / db.folder;
    ASSERT_TRUE(std::filesystem::is_directory(folder)) << folder;
    const auto networks = filesIn(folder, ".nbrdf");
    EXPECT_EQ(networks.size(), db.networks) << folder;
    for (const auto& file : networks) {
      const NeuralBrdf n = NeuralBrdf::load(file);
      EXPECT_EQ(n.label(), db.label) << file;
      EXPECT_EQ(n.material(), file.stem().string()) << file;
    }
  }
}

// Every parameter file of a database folder finds its network beside it (resolveMeasured's last place), so
// a clone with nothing beside it has measured data for each: MERL's 100 now, the others' as they are added.
TEST(MaterialLibrary, EveryParameterFileHasItsNetworkBeside) {
  const NoMerlDir noMerlDir;
  size_t files = 0;
  for (const Database& db : kDatabases) {
    const auto folder = libraryDir() / db.folder;
    ASSERT_TRUE(std::filesystem::is_directory(folder)) << folder;
    for (const auto& file : filesIn(folder, ".toml")) {
      const MaterialFile m = loadMaterialFile(file);
      const auto network = folder / (m.name + ".nbrdf");
      EXPECT_TRUE(std::filesystem::is_regular_file(network)) << file << " has no " << network.filename();
      EXPECT_EQ(resolveMeasured(m.measured, {}, folder), network) << file << ": measured = \"" << m.measured << "\"";
      ++files;
    }
  }
  EXPECT_GE(files, 100u);
}

}  // namespace glossy::test
