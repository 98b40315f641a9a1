#include "renderer/app/destination.h"

#include "materials/core/input_error.h"

#include <unistd.h>

namespace glossy::app {

namespace {

std::string named(std::string_view option, const std::filesystem::path& path) {
  return std::string(option) + " " + path.string();
}

// The folder a write under `folder` lands in first: itself if it exists, else its nearest existing ancestor.
void checkWritableFolder(const std::filesystem::path& folder, std::string_view option, const std::filesystem::path& path,
                         bool create) {
  std::error_code ec;
  std::filesystem::path f = folder.empty() ? std::filesystem::path(".") : folder;
  if (create)
    while (!std::filesystem::exists(f, ec) && f.has_parent_path() && f.parent_path() != f) f = f.parent_path();
  if (create && !std::filesystem::exists(f, ec)) f = ".";
  if (!std::filesystem::exists(f, ec)) throw InputError(named(option, path) + ": folder " + f.string() + " does not exist");
  if (!std::filesystem::is_directory(f, ec)) throw InputError(named(option, path) + ": " + f.string() + " is not a folder");
  if (::access(f.c_str(), W_OK | X_OK) != 0) throw InputError(named(option, path) + ": folder " + f.string() + " is not writable");
}

}  // namespace

void checkOutputFile(const std::filesystem::path& path, std::string_view option,
                     std::initializer_list<std::string_view> extensions, Folder folder) {
  if (path.empty()) throw InputError(std::string(option) + ": empty path");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(named(option, path) + ": is a folder, not a file");
  std::string wanted;
  bool ok = false;
  for (std::string_view e : extensions) {
    ok = ok || path.extension() == e;
    wanted.append(wanted.empty() ? "" : " or ").append(e);
  }
  if (!ok) throw InputError(named(option, path) + ": the file name must end in " + wanted);
  checkWritableFolder(path.parent_path(), option, path, folder == Folder::Create);
  if (std::filesystem::exists(path, ec) && ::access(path.c_str(), W_OK) != 0)
    throw InputError(named(option, path) + ": is not writable");
}

void checkOutputFolder(const std::filesystem::path& path, std::string_view option) {
  if (path.empty()) throw InputError(std::string(option) + ": empty path");
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_directory(path, ec))
    throw InputError(named(option, path) + ": exists and is not a folder");
  checkWritableFolder(path, option, path, true);
}

}  // namespace glossy::app
