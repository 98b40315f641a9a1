// What stays inside a folder: the one rule by which the readers of input folders (input_folder.h)
// and the writers of output folders keep to the folder they were given. A symlink is
// followed only while it stays inside; one leading out would make a reader publish any file the user can
// read, and a writer write, and overwrite, files anywhere (`OUT/analysis -> ~/thesis`).
#pragma once

#include <filesystem>
#include <string_view>

namespace glossy {

// Whether `path`, resolved through every symlink, lies strictly inside `folder`, resolved likewise. Both must
// exist (canonical paths); false when either cannot be resolved.
bool liesInside(const std::filesystem::path& folder, const std::filesystem::path& path);

// Before a command writes `file` below its output folder `root` (the folder given by `option`, "-o"): every
// part of the way that exists — the folders down to `file`, and `file` itself — must resolve inside `root`
// (the missing rest is made as plain folders). Throws InputError "OPTION ROOT: REL leads out of it (a symlink
// to ...); glossy writes only inside ROOT", or "... is a symlink to nothing" for a dangling one. A symlink
// that stays inside is followed, as the readers follow it.
void checkWriteInside(const std::filesystem::path& root, const std::filesystem::path& file, std::string_view option);

}  // namespace glossy
