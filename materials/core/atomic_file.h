// Writing outputs so that a reader never sees half a file: write a temporary beside the target, then
// rename it over the target (atomic on POSIX within one file system).
#pragma once

#include <filesystem>
#include <string_view>

namespace glossy {

// Throws std::runtime_error naming the path if anything fails; the temporary is removed on failure.
void writeFileAtomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace glossy
