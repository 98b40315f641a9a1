// A folder written whole, as atomic_file.h writes a file whole: its files go into a fresh folder beside it,
// `.NAME.tmp.glossy-XXXXXX`, which then takes the folder's place in one rename (an exchange when the folder is
// there, the old one then removed). So what the folder holds is always one run's: a rerun that writes fewer
// files leaves none of the earlier run's behind, and a run that fails half-way leaves the earlier folder
// untouched, never old and new files mixed.
//
// Callers hold the folder's OutputLock (output_lock.h) while they write and swap, so that they may also
// clear the fresh folders a killed run left (named as above, and only those).
#pragma once

#include <filesystem>

namespace glossy {

class FreshFolder {
 public:
  // Makes the fresh folder beside `target`, first removing those left by runs killed while writing one.
  explicit FreshFolder(const std::filesystem::path& target);
  ~FreshFolder();  // removes the fresh folder unless it took the target's place
  FreshFolder(const FreshFolder&) = delete;
  FreshFolder& operator=(const FreshFolder&) = delete;

  const std::filesystem::path& path() const { return fresh_; }
  // Puts the fresh folder in the target's place, then removes the one it replaced. Throws
  // std::runtime_error naming the target if the rename fails (the target is then as it was).
  void replaceTarget();

 private:
  std::filesystem::path target_, fresh_;
  bool swapped_ = false;
};

}  // namespace glossy
