#include "renderer/util/output_lock.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace glossy {

namespace {

// What glossy writes into a lock file it makes, so that one left by a killed run is known to be glossy's.
constexpr std::string_view kMarker = "glossy output lock\n";

bool holdsMarker(int fd) {
  char text[64] = {};
  const ssize_t n = ::pread(fd, text, sizeof text, 0);
  return n == ssize_t(kMarker.size()) && std::string_view(text, size_t(n)) == kMarker;
}

bool sameFile(int fd, const std::filesystem::path& path) {
  struct stat a {}, b {};
  return ::fstat(fd, &a) == 0 && ::lstat(path.c_str(), &b) == 0 && a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

bool regularFile(int fd) {
  struct stat s {};
  return ::fstat(fd, &s) == 0 && S_ISREG(s.st_mode);
}

}  // namespace

void OutputLock::removeMadeFolders() const {
  for (const std::filesystem::path& f : madeFolders_)
    if (::rmdir(f.c_str()) != 0) break;  // not empty: the output (or another run's) is in it
}

OutputLock::OutputLock(const std::filesystem::path& destination, std::string_view option, Busy busy) {
  try {
    take(destination, option, busy);
  } catch (...) {
    if (fd_ >= 0) ::close(fd_);
    removeMadeFolders();
    throw;
  }
}

void OutputLock::take(const std::filesystem::path& destination, std::string_view option, Busy busy) {
  const std::string where = std::string(option) + ": " + destination.string();
  const std::filesystem::path folder = destination.has_parent_path() ? destination.parent_path() : std::filesystem::path(".");
  // Appended in place: GCC 12's -Wrestrict misreads the inlined `"." + name + ".lock"` as an overlapping copy.
  std::string lockName = ".";
  lockName.append(destination.filename().string()).append(".lock");
  lockPath_ = folder / lockName;
  std::error_code ec;
  for (std::filesystem::path f = folder; !f.empty() && !std::filesystem::exists(f, ec); f = f.parent_path()) {
    madeFolders_.push_back(f);
    if (f == f.parent_path()) break;
  }
  // A few tries: a run releasing its lock removes the file (and maybe the folder) between our steps.
  for (int attempt = 0;; ++attempt) {
    if (!std::filesystem::create_directories(folder, ec) && ec)
      throw InputError(where + ": cannot make its folder: " + ec.message());
    // O_EXCL first: a file this run makes is glossy's for sure. O_NOFOLLOW: a symlink in the lock's place
    // does not lead the lock file elsewhere.
    bool made = true;
    fd_ = ::open(lockPath_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd_ < 0 && errno == EEXIST) {  // another run's, a killed run's, or not glossy's
      made = false;
      fd_ = ::open(lockPath_.c_str(), O_RDWR | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    }
    if (fd_ < 0) {
      if ((errno == ENOENT || errno == EEXIST) && attempt < 8) continue;
      throw InputError(where + ": cannot make the lock file " + lockPath_.string() + ": " + std::strerror(errno));
    }
    if (!regularFile(fd_)) throw InputError(where + ": its lock file " + lockPath_.string() + " is not a file");
    if (::flock(fd_, busy == Busy::Wait ? LOCK_EX : LOCK_EX | LOCK_NB) != 0) {
      const int e = errno;
      ::close(fd_);
      fd_ = -1;
      if (e == EWOULDBLOCK) throw OutputBusy(where + " is being written by another glossy process");
      throw InputError(where + ": cannot lock " + lockPath_.string() + ": " + std::strerror(e));
    }
    // The holder removes the file when it releases it: a lock taken on a file no longer at the path
    // excludes no one, so the one now there is taken instead.
    if (sameFile(fd_, lockPath_)) {
      if (made) ours_ = ::pwrite(fd_, kMarker.data(), kMarker.size(), 0) == ssize_t(kMarker.size());
      else ours_ = holdsMarker(fd_);
      return;
    }
    ::close(fd_);
    fd_ = -1;
    if (attempt >= 8) throw InputError(where + ": cannot lock " + lockPath_.string() + ": it keeps being replaced");
  }
}

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  // Removed while still held, so that whoever opened it meanwhile finds it gone (see above).
  if (ours_) ::unlink(lockPath_.c_str());
  ::close(fd_);
  removeMadeFolders();
}

}  // namespace glossy
