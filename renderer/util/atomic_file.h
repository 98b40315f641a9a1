// Writing outputs so that a reader never sees half a file: write a temporary beside the target, then
// rename it over the target (atomic on POSIX within one file system). A temporary that exists when the
// process is stopped by SIGINT, SIGTERM or SIGHUP is removed by the signal handler, once installed.
#pragma once

#include <filesystem>
#include <string_view>

namespace glossy {

// Throws std::runtime_error naming the path if anything fails; the temporary is removed on failure.
void writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

// Installs handlers for SIGINT, SIGTERM and SIGHUP that remove the temporaries being written, then end the
// process by the same signal with its default action (so it still stops at once, with the usual status).
void removeTemporariesOnSignal();

// A temporary file beside `path` (`path`.tmp.glossy-XXXXXX, created empty), known to the signal handler until
// released by rename or removal. Neither copyable nor movable: the handler knows it by its slot.
// Whether `file` is named as a PendingTemporary of `target` is (TARGET.tmp.glossy- and six characters): what
// a run killed outright may leave. Only such files may be cleaned up for it; a file merely named like an
// older pattern (TARGET.tmp.*) is someone else's.
bool isTemporaryOf(const std::filesystem::path& file, const std::filesystem::path& target);

class PendingTemporary {
 public:
  explicit PendingTemporary(const std::filesystem::path& path);
  ~PendingTemporary();  // removes the file unless it was renamed into place
  PendingTemporary(const PendingTemporary&) = delete;
  PendingTemporary& operator=(const PendingTemporary&) = delete;

  int fd() const { return fd_; }
  // Closes the descriptor; returns close()'s result (errno set on failure).
  int close();
  // Renames the temporary over `target`; returns rename()'s result. On success the file is no longer ours.
  int renameTo(const std::filesystem::path& target);

 private:
  std::filesystem::path tmp_;
  int fd_ = -1;
  int slot_ = -1;
};

}  // namespace glossy
