// What is refused about a glTF file before tinygltf reads it: JSON that does not parse, a version other than
// 2.x, and required extensions the loader cannot honour. Checked on the raw JSON first, so a Draco-compressed
// or glTF 1.0 file is refused for that reason rather than for whatever tinygltf or the loader trips on next.
#pragma once

#include <filesystem>
#include <string>

namespace glossy {

// Throws InputError naming the file (and the extension or the version) when the file must be refused.
void preflightGltf(const std::filesystem::path& path);

}  // namespace glossy
