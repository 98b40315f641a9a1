// glossy sheets' resuming: a sheet on disk is kept only if it is whole and was made with the settings
// of this run; anything else (a 0-byte or truncated EXR, a missing layer, a PNG that is missing, does not
// open as a PNG or is not the size the settings give, other settings) is rendered again. The settings travel
// in the EXR as the glossy:settings attribute. Runs sharing a folder take turns per sheet (each holds the
// sheet's OutputLock, renderer/util/output_lock.h), and the one holding a sheet clears the temporaries an
// interrupted write of it left — glossy's own only.
#pragma once

#include "renderer/sheet/sheet.h"

#include <filesystem>
#include <string>

namespace glossy::app {

inline constexpr const char* kSettingsAttribute = "glossy:settings";

// A digest of a file's bytes (FNV-1a, 64 bits, in hex): a material file edited since its sheet was made
// gives another. Throws InputError naming the file if it cannot be read.
std::string contentDigest(const std::filesystem::path& path);

// "" when `exr` and the PNG beside it form a complete sheet whose glossy:settings is `settings` and whose
// PNG is the size of `sheet`'s panels side by side; else why not.
std::string whyIncomplete(const std::filesystem::path& exr, const std::string& settings, const SheetSettings& sheet);

// Removes the temporaries an interrupted write of sheet `exr` left beside it (its EXR's and PNG's, named as
// atomic_file.h names them; a file merely named like them is not glossy's and stays); returns how many.
// Call it only holding the sheet's lock: no live run is writing them then.
size_t removeStaleTemporaries(const std::filesystem::path& exr);

}  // namespace glossy::app
