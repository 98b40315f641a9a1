// One writer per destination: a command holds the destination's lock from before its work until its output
// is in place, so that two runs writing one file (two `glossy sheet -o x.exr`, the shards of a job array
// sharing a folder) never interleave their files — an EXR of one run beside the PNG of the other, both
// exiting 0. The second run is refused, naming the destination, before it starts.
//
// The lock is an flock on a hidden file beside the destination, `.NAME.lock` (so it works wherever the
// destination's folder is, on shared cluster storage too). It is removed when released: a command leaves
// nothing it did not need. A lock file left by a run that was killed outright is reused and then removed;
// a file of that name glossy did not make is used as it is and never removed. Missing folders on the way to
// the destination are made when the lock is taken (the lock file needs one), and removed again on release if
// they are still empty (the command failed before writing).
#pragma once

#include "materials/core/input_error.h"

#include <filesystem>
#include <string_view>
#include <vector>

namespace glossy {

// Another glossy process holds the destination's lock.
class OutputBusy : public InputError {
 public:
  using InputError::InputError;
};

class OutputLock {
 public:
  // What to do when another process holds the lock: refuse (a second writer of one output), or wait for it
  // (a short step several runs of one job take in turn, such as claiming a study's folder).
  enum class Busy { Refuse, Wait };

  // Throws OutputBusy "OPTION: PATH is being written by another glossy process" when another process holds
  // it (Busy::Refuse), InputError naming the option and path when the lock file cannot be made.
  OutputLock(const std::filesystem::path& destination, std::string_view option, Busy busy = Busy::Refuse);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  void take(const std::filesystem::path& destination, std::string_view option, Busy busy);
  void removeMadeFolders() const;

  std::filesystem::path lockPath_;
  std::vector<std::filesystem::path> madeFolders_;  // innermost first
  int fd_ = -1;
  bool ours_ = false;  // the lock file is glossy's: removed on release
};

}  // namespace glossy
