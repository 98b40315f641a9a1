#include "tests/fuzz/fuzz_temp_dir.h"

#include <unistd.h>

#include <fstream>
#include <stdexcept>

namespace glossy::fuzz {

namespace {

class ProcessDir {
 public:
  ProcessDir() : path_(std::filesystem::temp_directory_path() / ("glossy-fuzz-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~ProcessDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

const std::filesystem::path& processDir() {
  static const ProcessDir dir;
  return dir.path();
}

}  // namespace

TempFile::TempFile(const std::string& name, Bytes data) : path_(processDir() / name) {
  std::ofstream out(path_, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data.data()), std::streamsize(data.size()));
  // Not InputError: a failure here is the harness's, never the input's, and must not pass as a refusal.
  if (!out.flush()) throw std::runtime_error("fuzz harness: cannot write " + path_.string());
}

TempFile::~TempFile() {
  std::error_code ec;
  std::filesystem::remove(path_, ec);
}

}  // namespace glossy::fuzz
