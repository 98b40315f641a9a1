// Where the entries put their input for a loader that reads only from a path: a folder of this process's
// own (so that concurrent fuzzers and tests never share a file), removed when the process exits normally.
#pragma once

#include "tests/fuzz/fuzz_entries.h"

#include <filesystem>
#include <string>

namespace glossy::fuzz {

// The bytes as the file NAME in the process's folder; removed again when this goes out of scope.
class TempFile {
 public:
  TempFile(const std::string& name, Bytes data);
  ~TempFile();
  TempFile(const TempFile&) = delete;
  TempFile& operator=(const TempFile&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace glossy::fuzz
