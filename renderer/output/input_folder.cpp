// Reading regular files inside an input folder (input_folder.h).
#include "renderer/output/input_folder.h"

#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "renderer/output/inside_folder.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>

namespace glossy {

namespace fs = std::filesystem;

namespace {

// The real path of `file`, checked to be a regular file inside `folder`.
fs::path realInside(const fs::path& folder, const fs::path& file, std::string_view what) {
  const std::string where = file.string() + ": ";
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(file, ec))) throw InputError(where + "missing (the " + std::string(what) + ")");
  const fs::path real = fs::canonical(file, ec);
  if (ec) throw InputError(where + "a symlink to nothing (the " + std::string(what) + ")");
  const fs::path root = fs::canonical(folder, ec);
  if (ec) throw InputError(folder.string() + ": cannot resolve: " + ec.message());
  if (!liesInside(root, real))
    throw InputError(where + "a symlink leading out of " + folder.string() + "; the report reads only files inside it");
  const fs::file_status s = fs::status(real, ec);
  if (fs::is_directory(s)) throw InputError(where + "a folder, not a " + std::string(what));
  if (!fs::is_regular_file(s)) throw InputError(where + "not a regular file (a FIFO, device or socket), not a " + std::string(what));
  return real;
}

}  // namespace

void checkInputFile(const fs::path& folder, const fs::path& file, std::string_view what) { realInside(folder, file, what); }

std::string readInputFile(const fs::path& folder, const fs::path& file, std::uintmax_t maxBytes, std::string_view what) {
  const fs::path real = realInside(folder, file, what);
  const std::string where = file.string() + ": ";
  const Descriptor d{::open(real.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY)};
  if (d.fd < 0) throw InputError(where + "cannot open: " + std::strerror(errno));
  struct stat st {};
  if (::fstat(d.fd, &st) != 0 || !S_ISREG(st.st_mode)) throw InputError(where + "not a regular file, not a " + std::string(what));
  if (st.st_size < 0 || std::uintmax_t(st.st_size) > maxBytes)
    throw InputError(where + std::to_string(st.st_size) + " bytes, too large for a " + std::string(what) + " (at most " +
                     std::to_string(maxBytes) + ")");
  return readOpenFile(d.fd, std::uintmax_t(st.st_size), where);
}

}  // namespace glossy
