// A folder glossy fills, and its manifest (owned_folder.h).
#include "renderer/output/owned_folder.h"

#include "renderer/util/atomic_file.h"
#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "materials/core/text.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <fcntl.h>
#include <set>
#include <sys/stat.h>

namespace glossy {

namespace fs = std::filesystem;

namespace {

constexpr size_t kMaxManifestBytes = size_t(16) << 20;
constexpr size_t kMaxPathLength = 1000;

// One component of a listed path: letters, digits, '_', '.', '+', '-', starting with a letter or digit, so
// never "", "." or "..", never hidden. A manifest can only name files below its folder.
bool isPlainComponent(const std::string& name) {
  if (name.empty() || name.size() > 200 || !std::isalnum((unsigned char)name[0])) return false;
  return std::all_of(name.begin(), name.end(),
                     [](char c) { return std::isalnum((unsigned char)c) || c == '_' || c == '.' || c == '+' || c == '-'; });
}

std::vector<std::string> components(const std::string& file) {
  std::vector<std::string> parts;
  size_t start = 0;
  for (;;) {
    const size_t slash = file.find('/', start);
    parts.push_back(file.substr(start, slash == std::string::npos ? std::string::npos : slash - start));
    if (slash == std::string::npos) return parts;
    start = slash + 1;
  }
}

bool isListablePath(const std::string& file) {
  if (file.empty() || file.size() > kMaxPathLength) return false;
  const std::vector<std::string> parts = components(file);
  return std::all_of(parts.begin(), parts.end(), isPlainComponent);
}

// The first folder on the way from `root` to `file` that exists and is a symlink or not a folder; "" if none.
std::string blockedFolder(const fs::path& root, const std::string& file) {
  const std::vector<std::string> parts = components(file);
  fs::path p = root;
  std::string rel;
  for (size_t k = 0; k + 1 < parts.size(); ++k) {
    p /= parts[k];
    rel += (rel.empty() ? "" : "/") + parts[k];
    std::error_code ec;
    const fs::file_status s = fs::symlink_status(p, ec);
    if (!fs::exists(s)) return "";
    if (fs::is_symlink(s) || !fs::is_directory(s)) return rel;
  }
  return "";
}

// The manifest's bytes: a regular file (not a symlink, not a FIFO: opened without blocking), of bounded size.
std::string readManifestBytes(const fs::path& path, const std::string& where) {
  const std::string manifest = where + ": its " + OwnedFolder::kManifest;
  const Descriptor d{::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (d.fd < 0) throw InputError(manifest + " cannot be read (a symlink, or unreadable)");
  struct stat st {};
  if (::fstat(d.fd, &st) != 0 || !S_ISREG(st.st_mode) || uint64_t(st.st_size) > kMaxManifestBytes)
    throw InputError(manifest + " is not a regular file of at most 16 MB");
  return readOpenFile(d.fd, uint64_t(st.st_size), manifest + ": ");
}

}  // namespace

OwnedFolder::OwnedFolder(const fs::path& folder, std::string command, std::string option)
    : root_(folder), command_(std::move(command)), option_(std::move(option)) {
  if (folder.empty()) throw InputError(option_ + ": an empty path");
  std::error_code ec;
  const fs::file_status s = fs::status(folder, ec);
  if (!fs::exists(s)) return;
  if (!fs::is_directory(s)) throw InputError(where() + ": is a file, not a folder");
  const fs::file_status m = fs::symlink_status(folder / kManifest, ec);
  if (!fs::exists(m)) {
    fs::directory_iterator it(folder, ec);
    if (ec) throw InputError(where() + ": cannot list: " + ec.message());
    if (it == fs::directory_iterator()) return;
    throw InputError(where() + ": a folder that is not empty and that glossy did not fill (no " + kManifest + "); not writing into it");
  }
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(readManifestBytes(folder / kManifest, where()));
  } catch (const nlohmann::json::exception&) {
    throw InputError(where() + ": its " + kManifest + " is not JSON; not writing into it");
  }
  if (!j.is_object() || !j.contains("command") || !j["command"].is_string() || !j.contains("files") || !j["files"].is_array())
    throw InputError(where() + ": its " + kManifest + " is not one glossy writes; not writing into it");
  const std::string made = j["command"].get<std::string>();
  if (made != command_)
    throw InputError(where() + ": holds the output of '" + printableLine(made, 40) + "', not of '" + command_ + "'; not writing into it");
  for (const nlohmann::json& f : j["files"]) {
    if (!f.is_string() || !isListablePath(f.get<std::string>()))
      throw InputError(where() + ": its " + kManifest + " lists a file that is not a plain path below it; not writing into it");
    earlier_.push_back(f.get<std::string>());
  }
}

std::string OwnedFolder::where() const { return option_ + " " + root_.string(); }

void OwnedFolder::plan(const std::vector<std::string>& files) {
  const std::set<std::string> earlier(earlier_.begin(), earlier_.end());
  std::set<std::string> planned;
  for (const std::string& f : files) {
    if (!isListablePath(f)) throw std::logic_error(where() + ": '" + f + "' is not a plain path");
    if (!planned.insert(f).second) continue;
    if (const std::string blocked = blockedFolder(root_, f); !blocked.empty())
      throw InputError(where() + ": " + blocked + " is a symlink or a file, where glossy would make a folder; not writing through it");
    std::error_code ec;
    const fs::file_status s = fs::symlink_status(root_ / f, ec);
    if (fs::is_directory(s)) throw InputError(where() + ": " + f + " is a folder, where glossy would write a file");
    if (fs::exists(s) && !earlier.count(f))
      throw InputError(where() + ": " + f + " is there and glossy did not write it; not replacing it");
  }
  planned_.assign(planned.begin(), planned.end());
  std::error_code ec;
  fs::create_directories(root_, ec);
  if (ec) throw std::runtime_error(root_.string() + ": cannot create the folder: " + ec.message());
  std::set<std::string> both = planned;
  both.insert(earlier.begin(), earlier.end());
  writeManifest({both.begin(), both.end()});
}

void OwnedFolder::finish() {
  writeManifest(planned_);
  const std::set<std::string> planned(planned_.begin(), planned_.end());
  for (const std::string& f : earlier_) {
    // Only through folders glossy made: a folder replaced by a symlink since is not followed.
    if (planned.count(f) || !blockedFolder(root_, f).empty()) continue;
    std::error_code ec;
    const fs::file_status s = fs::symlink_status(root_ / f, ec);
    if (!fs::is_regular_file(s) && !fs::is_symlink(s)) continue;
    fs::remove(root_ / f, ec);
    // Then its folders below the root, deepest first, while they are empty.
    std::vector<std::string> parts = components(f);
    for (parts.pop_back(); !parts.empty(); parts.pop_back()) {
      fs::path dir = root_;
      for (const std::string& part : parts) dir /= part;
      if (!fs::is_empty(dir, ec) || ec || !fs::remove(dir, ec)) break;
    }
  }
  earlier_ = planned_;
}

void OwnedFolder::writeManifest(const std::vector<std::string>& files) const {
  nlohmann::ordered_json j;
  j["command"] = command_;
  j["files"] = files;
  writeFileAtomically(root_ / kManifest, j.dump(1) + "\n");
}

}  // namespace glossy
