// Reading a whole input file (material TOML, network, supplement text) with the checks hostile paths need:
// a folder, a device or FIFO (a material symlinked to /dev/zero would otherwise be read until memory runs
// out) and a file larger than any such input can be are refused as bad input, naming the file, before
// anything is read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace glossy {

// The file's bytes. Throws InputError "PATH: ..." unless it is a regular file (symlinks followed) of at
// most `maxBytes`; `kind` names what it should be ("material file").
std::string readInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes, std::string_view kind);

}  // namespace glossy
