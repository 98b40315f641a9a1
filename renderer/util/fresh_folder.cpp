// A folder written whole (fresh_folder.h).
#include "renderer/util/fresh_folder.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <random>
#include <stdexcept>
#include <string>
#include <sys/stat.h>

namespace glossy {

namespace fs = std::filesystem;

namespace {

// The fresh folders' names: "." + TARGET + kInfix + six characters mkdtemp chooses.
constexpr std::string_view kInfix = ".tmp.glossy-";
constexpr size_t kRandom = 6;

std::string prefixOf(const fs::path& target) {
  std::string prefix = ".";
  prefix.append(target.filename().string()).append(kInfix);
  return prefix;
}

fs::path folderOf(const fs::path& target) { return target.has_parent_path() ? target.parent_path() : fs::path("."); }

}  // namespace

FreshFolder::FreshFolder(const fs::path& target) : target_(target) {
  const fs::path folder = folderOf(target);
  const std::string prefix = prefixOf(target);
  std::error_code ec;
  // A killed run's fresh folders: named so by glossy alone, folders (never a link), removed with what they hold.
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    std::error_code sec;
    if (name.size() == prefix.size() + kRandom && name.starts_with(prefix) && it->symlink_status(sec).type() == fs::file_type::directory)
      fs::remove_all(it->path(), sec);
  }
  // Not mkdtemp: its folder is private (0700), and the fresh folder becomes the target, which should have
  // the permissions any folder made here has (0777 less the umask), as the earlier one had.
  static constexpr std::string_view kLetters = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789";
  std::random_device seed;
  std::mt19937_64 random(seed());
  for (int attempt = 0; attempt < 100; ++attempt) {
    std::string name = prefix;
    for (size_t k = 0; k < kRandom; ++k) name += kLetters[random() % kLetters.size()];
    const fs::path path = folder / name;
    if (::mkdir(path.c_str(), 0777) == 0) {
      fresh_ = path;
      return;
    }
    if (errno != EEXIST) break;
  }
  throw std::runtime_error(target.string() + ": cannot make a folder beside it: " + std::strerror(errno));
}

FreshFolder::~FreshFolder() {
  std::error_code ec;
  fs::remove_all(fresh_, ec);  // after a swap, the folder it replaced; else the unfinished one
}

void FreshFolder::replaceTarget() {
  if (swapped_) throw std::logic_error(target_.string() + ": replaced twice");
  std::error_code ec;
  if (fs::exists(fs::symlink_status(target_, ec))) {
    // One step for readers: the target is the old folder or the new one, never missing, never half of each.
    if (::renameat2(AT_FDCWD, fresh_.c_str(), AT_FDCWD, target_.c_str(), RENAME_EXCHANGE) != 0)
      throw std::runtime_error(target_.string() + ": cannot put the new folder in its place: " + std::strerror(errno));
  } else if (::rename(fresh_.c_str(), target_.c_str()) != 0) {
    throw std::runtime_error(target_.string() + ": cannot put the new folder in its place: " + std::strerror(errno));
  }
  swapped_ = true;
  // fresh_ now names the old folder (or nothing), which the destructor removes.
}

}  // namespace glossy
