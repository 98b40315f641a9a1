#include "renderer/cli/sheet_resume.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/image/exr_image.h"
#include "renderer/sheet/sheet.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <fstream>
#include <iterator>

namespace glossy::cli {

std::string contentDigest(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open");
  uint64_t h = 0xcbf29ce484222325ull;
  for (auto it = std::istreambuf_iterator<char>(in); it != std::istreambuf_iterator<char>(); ++it)
    h = (h ^ static_cast<unsigned char>(*it)) * 0x100000001b3ull;
  if (in.bad()) throw InputError(path.string() + ": read failed");
  return formatted("%016llx", static_cast<unsigned long long>(h));
}

std::string whyIncomplete(const std::filesystem::path& exr, const std::string& settings) {
  std::error_code ec;
  const std::filesystem::path png = std::filesystem::path(exr).replace_extension(".png");
  if (!std::filesystem::is_regular_file(exr, ec)) return "no EXR";
  if (!std::filesystem::is_regular_file(png, ec)) return "no PNG";
  if (std::filesystem::file_size(png, ec) == 0) return "empty PNG";
  try {
    const std::string made = readImageAttribute(exr, kSettingsAttribute);
    if (made != settings) return made.empty() ? "EXR without glossy:settings" : "made with other settings";
    // Reading every layer's pixels also catches a file cut short after its header.
    for (const SheetPanel& p : sheetPanels()) readImageLayer(exr, p.layer);
  } catch (const std::exception& e) {
    return std::string("unreadable EXR (") + e.what() + ")";
  }
  return "";
}

size_t removeStaleTemporaries(const std::filesystem::path& folder, const std::string& name) {
  std::error_code ec;
  size_t removed = 0;
  for (const auto& e : std::filesystem::directory_iterator(folder, ec)) {
    const std::string f = e.path().filename().string();
    if ((f.starts_with(name + ".exr.tmp.") || f.starts_with(name + ".png.tmp.")) && e.is_regular_file(ec) &&
        std::filesystem::remove(e.path(), ec))
      ++removed;
  }
  return removed;
}

SheetLock::SheetLock(const std::filesystem::path& folder, const std::string& name) {
  const std::filesystem::path path = folder / ("." + name + ".lock");
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError(path.string() + ": cannot open the sheet's lock file: " + std::strerror(errno));
  held_ = ::flock(fd_, LOCK_EX | LOCK_NB) == 0;
}

SheetLock::~SheetLock() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace glossy::cli
