#include "renderer/util/data_dir.h"

namespace glossy {

namespace {

std::filesystem::path& current() {
  static std::filesystem::path dir = GLOSSY_SOURCE_DIR;
  return dir;
}

}  // namespace

std::filesystem::path dataDir() { return current(); }

std::filesystem::path materialLibraryDir() {
  std::error_code ec;
  if (std::filesystem::exists("materials/library/merl/alum-bronze.toml", ec)) return "materials/library";
  return dataDir() / "materials/library";
}

void setDataDir(std::filesystem::path dir) { current() = std::move(dir); }

}  // namespace glossy
