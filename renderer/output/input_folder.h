// The files a command reads from its input folders (the report's SHEETS_DIR and PLOTS_DIR, a study's output
// folder): regular files inside the folder.
// A symlink is followed only while it stays inside the folder — one leading elsewhere could copy any file
// the user can read into a site meant for publishing — and a FIFO, device or socket is refused without being
// opened, so nothing blocks or reads forever.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace glossy {

// Throws InputError "FILE: ..." unless `file` is a regular file whose real path lies inside `folder`'s.
// `what` names what it should be ("sheet").
void checkInputFile(const std::filesystem::path& folder, const std::filesystem::path& file, std::string_view what);

// The bytes of such a file, at most `maxBytes`: checked as above, then opened without following a last
// symlink swapped in since and without blocking, and checked again on the open descriptor.
std::string readInputFile(const std::filesystem::path& folder, const std::filesystem::path& file, std::uintmax_t maxBytes,
                          std::string_view what);

}  // namespace glossy
