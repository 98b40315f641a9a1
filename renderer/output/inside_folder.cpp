// Staying inside a folder, for readers and writers alike (inside_folder.h).
#include "renderer/output/inside_folder.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"

namespace glossy {

namespace fs = std::filesystem;

bool liesInside(const fs::path& folder, const fs::path& path) {
  std::error_code ec;
  const fs::path root = fs::canonical(folder, ec);
  if (ec) return false;
  const fs::path real = fs::canonical(path, ec);
  if (ec) return false;
  // Inside: the root's components are a proper prefix of the path's.
  auto r = root.begin(), p = real.begin();
  for (; r != root.end() && p != real.end() && *r == *p; ++r, ++p) {}
  return r == root.end() && p != real.end();
}

void checkWriteInside(const fs::path& root, const fs::path& file, std::string_view option) {
  const std::string where = std::string(option) + " " + printableLine(root.string(), 200);
  const fs::path relative = file.lexically_relative(root);
  if (relative.empty() || *relative.begin() == "..")
    throw std::logic_error(file.string() + " is not below " + root.string());
  // Down from the root, every part that is there; the first that is missing ends the check (the rest is
  // made by the writer, below a folder known to be inside).
  fs::path p = root;
  for (const fs::path& part : relative) {
    p /= part;
    std::error_code ec;
    const fs::file_status s = fs::symlink_status(p, ec);
    if (!fs::exists(s)) return;
    if (!fs::is_symlink(s)) continue;
    const std::string rel = printableLine(p.lexically_relative(root).generic_string(), 200);
    if (!fs::exists(fs::status(p, ec))) throw InputError(where + ": " + rel + " is a symlink to nothing; glossy does not write through it");
    if (!liesInside(root, p))
      throw InputError(where + ": " + rel + " is a symlink leading out of it (to " + printableLine(fs::canonical(p, ec).string(), 200) +
                       "); glossy writes only inside " + printableLine(root.string(), 200));
  }
}

}  // namespace glossy
