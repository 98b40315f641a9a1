#include "materials/core/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace glossy {

namespace {

std::runtime_error ioError(const std::filesystem::path& path, const char* what) {
  return std::runtime_error(path.string() + ": " + what + ": " + std::strerror(errno));
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& path, std::string_view contents) {
  std::string tmpl = path.string() + ".tmp.XXXXXX";
  int fd = mkstemp(tmpl.data());
  if (fd < 0) throw ioError(path, "cannot create a temporary file beside it");
  const std::filesystem::path tmp = tmpl;
  auto fail = [&](const char* what) {
    auto err = ioError(path, what);
    ::close(fd);
    std::error_code ignored;
    std::filesystem::remove(tmp, ignored);
    return err;
  };
  const char* p = contents.data();
  size_t left = contents.size();
  while (left > 0) {
    ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw fail("cannot write");
    }
    p += n;
    left -= static_cast<size_t>(n);
  }
  // mkstemp creates 0600; outputs are ordinary files.
  if (::fchmod(fd, 0644) != 0) throw fail("cannot set permissions");
  if (::fsync(fd) != 0) throw fail("cannot flush");
  const int closed = ::close(fd);
  fd = -1;  // closed either way: fail() must not close it again
  if (closed != 0) throw fail("cannot close");
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw fail("cannot rename the temporary file into place");
}

}  // namespace glossy
