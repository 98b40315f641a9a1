// Reading input files with the checks hostile paths need: a folder, a device or FIFO (a material symlinked
// to /dev/zero would otherwise be read until memory runs out; a FIFO would block the reader until someone
// writes to it) and a file larger than any such input can be are refused as bad input, naming the file,
// before anything is read. Every input goes through here: whole-file reads through readInputFile, paths
// handed to a library that opens them itself (OpenImageIO, tinygltf) through requireInputFile first.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace glossy {

// A file descriptor that closes itself.
struct Descriptor {
  int fd = -1;
  ~Descriptor();
};

// The file's size. Throws InputError "PATH: ..." unless it is a regular file (symlinks followed); `kind`
// names what it should be ("environment map"). Checked by its status first, so that a FIFO or device is
// never opened, then on a descriptor opened without blocking, so that one swapped in meanwhile is refused
// rather than waited on.
std::uintmax_t requireInputFile(const std::filesystem::path& path, std::string_view kind);

// The file's bytes. Throws InputError "PATH: ..." unless it is a regular file (symlinks followed) of at
// most `maxBytes`; `kind` names what it should be ("material file").
std::string readInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes, std::string_view kind);

// The bytes of an open regular file of `size` bytes, read to its end. Throws InputError "WHERE changed size
// while it was read" when it held more or fewer by then, "WHERE read failed (...)" on a read error.
std::string readOpenFile(int fd, std::uintmax_t size, const std::string& where);

}  // namespace glossy
