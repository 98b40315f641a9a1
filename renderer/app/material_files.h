// Which material files a job reads: the library, or the files and folders given.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace glossy::app {

// The material files `paths` name, sorted and each once: a folder stands for the *.toml files in it and its
// subfolders, anything else for itself. No paths: the library.
std::vector<std::filesystem::path> materialFiles(const std::vector<std::string>& paths);

}  // namespace glossy::app
