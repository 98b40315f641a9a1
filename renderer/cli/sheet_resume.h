// glossy sheets' resuming: a sheet on disk is kept only if it is whole and was made with the settings
// of this run; anything else (a 0-byte or truncated EXR, a missing layer or PNG, other settings) is
// rendered again. The settings travel in the EXR as the glossy:settings attribute. Runs sharing a folder
// take turns per sheet, and the one holding a sheet clears what an interrupted write of it left.
#pragma once

#include <filesystem>
#include <string>

namespace glossy::cli {

inline constexpr const char* kSettingsAttribute = "glossy:settings";

// A digest of a file's bytes (FNV-1a, 64 bits, in hex): a material file edited since its sheet was made
// gives another. Throws InputError naming the file if it cannot be read.
std::string contentDigest(const std::filesystem::path& path);

// "" when `exr` and the PNG beside it form a complete sheet whose glossy:settings is `settings`; else why not.
std::string whyIncomplete(const std::filesystem::path& exr, const std::string& settings);

// Removes the temporaries an interrupted write of sheet NAME left in `folder` (NAME.exr.tmp.XXXXXX,
// NAME.png.tmp.XXXXXX, see atomic_file.h); returns how many. Call it only holding the sheet's lock.
size_t removeStaleTemporaries(const std::filesystem::path& folder, const std::string& name);

// One sheet's lock, OUTDIR/.NAME.lock (flock): runs that share a folder (the shards of a job array, or a
// run started twice) each render a sheet only while holding its lock, so no two write one sheet and an
// EXR never pairs with another run's PNG. Released when destroyed, or when the process ends however it ends.
class SheetLock {
 public:
  SheetLock(const std::filesystem::path& folder, const std::string& name);  // throws InputError if it cannot open the file
  ~SheetLock();
  SheetLock(const SheetLock&) = delete;
  SheetLock& operator=(const SheetLock&) = delete;
  bool held() const { return held_; }  // false: another run is writing this sheet

 private:
  int fd_ = -1;
  bool held_ = false;
};

}  // namespace glossy::cli
