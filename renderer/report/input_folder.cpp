// Reading regular files inside an input folder (input_folder.h).
#include "renderer/report/input_folder.h"

#include "materials/core/input_error.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace glossy::report {

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
  // Inside: the root's components are a proper prefix of the file's.
  auto r = root.begin(), f = real.begin();
  for (; r != root.end() && f != real.end() && *r == *f; ++r, ++f) {}
  if (r != root.end() || f == real.end())
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
  const int fd = ::open(real.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) throw InputError(where + "cannot open: " + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw InputError(where + "not a regular file, not a " + std::string(what));
  }
  if (st.st_size < 0 || std::uintmax_t(st.st_size) > maxBytes) {
    ::close(fd);
    throw InputError(where + std::to_string(st.st_size) + " bytes, too large for a " + std::string(what) + " (at most " +
                     std::to_string(maxBytes) + ")");
  }
  // One byte more than its size asks for: a file that grows while it is read is refused, not cut.
  std::string bytes(size_t(st.st_size) + 1, '\0');
  size_t got = 0;
  for (;;) {
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    got += size_t(n);
    if (got == bytes.size()) break;
  }
  ::close(fd);
  if (got != size_t(st.st_size)) throw InputError(where + "changed size while it was read");
  bytes.resize(got);
  return bytes;
}

}  // namespace glossy::report
