// A digest of bytes, for telling whether an input changed since an output was made from it (a sheet's
// settings line, renderer/app/sheet_resume.h): FNV-1a, 64 bits, in hex. Not a cryptographic hash — it tells
// an edited file from the one a sheet was made with, not a file crafted to collide.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace glossy {

class Digest {
 public:
  // Each part with its length, so that "ab" + "c" and "a" + "bc" differ.
  Digest& add(std::string_view bytes);
  std::string hex() const;  // 16 hex digits

 private:
  void mix(std::string_view bytes);
  uint64_t h_ = 0xcbf29ce484222325ull;
};

// The digest of a file's bytes, read in pieces (an environment map may be larger than memory allows twice).
// Remembered for the run by the file's path, size and modification time, so that a batch checking many
// sheets of one measured table reads it once. Throws InputError naming the file (as `kind`) if it is not a
// regular file or cannot be read.
std::string fileDigest(const std::filesystem::path& path, std::string_view kind);

}  // namespace glossy
