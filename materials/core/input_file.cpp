#include "materials/core/input_file.h"

#include "materials/core/input_error.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace glossy {

namespace {

std::string notRegular(const struct stat& s) {
  if (S_ISDIR(s.st_mode)) return "is a folder, not a regular file";
  if (S_ISFIFO(s.st_mode)) return "is a FIFO, not a regular file";
  if (S_ISCHR(s.st_mode) || S_ISBLK(s.st_mode)) return "is a device, not a regular file";
  if (S_ISSOCK(s.st_mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

// Opens a regular file for reading, without blocking; its size in `size`.
Descriptor openRegular(const std::filesystem::path& path, std::string_view kind, std::uintmax_t& size) {
  const std::string where = path.string() + ": ";
  struct stat s {};
  if (::stat(path.c_str(), &s) != 0) {
    const int e = errno;
    throw InputError(where + "cannot open " + std::string(kind) +
                     (e == ENOENT || e == ENOTDIR ? ": not found" : ": " + std::string(std::strerror(e))));
  }
  if (!S_ISREG(s.st_mode)) throw InputError(where + notRegular(s));
  // O_NONBLOCK: should the path have become a FIFO since, opening it returns at once instead of waiting for
  // a writer; O_NOCTTY: a terminal never becomes the controlling one. Neither changes reading a regular file.
  Descriptor d{::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC)};
  if (d.fd < 0) throw InputError(where + "cannot open " + std::string(kind) + " (" + std::strerror(errno) + ")");
  if (::fstat(d.fd, &s) != 0) throw InputError(where + "cannot read its status (" + std::strerror(errno) + ")");
  if (!S_ISREG(s.st_mode)) throw InputError(where + notRegular(s));
  size = std::uintmax_t(s.st_size);
  return d;
}

}  // namespace

Descriptor::~Descriptor() {
  if (fd >= 0) ::close(fd);
}

std::uintmax_t requireInputFile(const std::filesystem::path& path, std::string_view kind) {
  std::uintmax_t size = 0;
  openRegular(path, kind, size);
  return size;
}

std::string readInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes, std::string_view kind) {
  const std::string where = path.string() + ": ";
  std::uintmax_t size = 0;
  const Descriptor d = openRegular(path, kind, size);
  if (size > maxBytes)
    throw InputError(where + std::to_string(size) + " bytes, too large for a " + std::string(kind) + " (at most " +
                     std::to_string(maxBytes) + ")");
  return readOpenFile(d.fd, size, where);
}

std::string readOpenFile(int fd, std::uintmax_t size, const std::string& where) {
  // One byte more than its size asks for: a file that changes while it is read is refused, not cut.
  std::string bytes(size_t(size) + 1, '\0');
  size_t got = 0;
  while (got < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + got, bytes.size() - got);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw InputError(where + "read failed (" + std::strerror(errno) + ")");
    if (n == 0) break;
    got += size_t(n);
  }
  if (got != size) throw InputError(where + "changed size while it was read");
  bytes.resize(size_t(size));
  return bytes;
}

}  // namespace glossy
