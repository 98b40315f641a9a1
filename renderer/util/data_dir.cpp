#include "renderer/util/data_dir.h"

namespace glossy {

namespace {

std::filesystem::path& current() {
  static std::filesystem::path dir = GLOSSY_SOURCE_DIR;
  return dir;
}

}  // namespace

std::filesystem::path dataDir() { return current(); }

void setDataDir(std::filesystem::path dir) { current() = std::move(dir); }

}  // namespace glossy
