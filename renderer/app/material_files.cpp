#include "renderer/app/material_files.h"

#include "renderer/util/data_dir.h"

#include <algorithm>

namespace glossy::app {

std::vector<std::filesystem::path> materialFiles(const std::vector<std::string>& paths) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  for (const std::string& p : paths.empty() ? std::vector<std::string>{materialLibraryDir().string()} : paths) {
    if (!std::filesystem::is_directory(p, ec)) {
      files.emplace_back(p);
      continue;
    }
    // Its subfolders too: the library keeps a folder per database. Links to folders are not followed, so a
    // link cannot make the walk endless.
    for (const auto& e : std::filesystem::recursive_directory_iterator(p))
      if (e.path().extension() == ".toml" && !e.is_directory()) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  return files;
}

}  // namespace glossy::app
