// Every input kept by the fuzzers (tests/fuzz/corpus/TARGET: inputs that reached new code; tests/fuzz/
// crashes/TARGET: inputs that once crashed a loader) goes through its target's entry again, in the normal
// build: each must be accepted or refused with InputError. A crash kills the suite, any other exception
// fails the test, and so does an input that makes a loader take gigabytes (it runs out of address space and
// throws std::bad_alloc), so a fix that is undone shows here without a fuzzer.
#include "materials/core/input_error.h"
#include "tests/fuzz/fuzz_entries.h"
#include "tests/support/test_support.h"

#include <gtest/gtest.h>

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <fstream>
#include <iterator>
#include <vector>

namespace glossy {
namespace {

std::vector<std::filesystem::path> filesIn(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  std::error_code ec;
  if (std::filesystem::is_directory(dir, ec))
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.is_regular_file() && e.path().filename().string().front() != '.') files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<uint8_t> bytesOf(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// Address space for the inputs: what the process has mapped now plus 2 GB, as the fuzzers' 2 GB memory limit
// (relative, so that a sanitizer's reserved shadow does not count). Restored when the test ends.
class AddressSpaceLimit {
 public:
  AddressSpaceLimit() {
    ::getrlimit(RLIMIT_AS, &saved_);
    std::ifstream statm("/proc/self/statm");
    unsigned long long pages = 0;
    statm >> pages;
    rlimit limit = saved_;
    limit.rlim_cur = std::min<rlim_t>(saved_.rlim_max, rlim_t(pages) * rlim_t(::sysconf(_SC_PAGESIZE)) + (rlim_t(2) << 30));
    active_ = pages > 0 && ::setrlimit(RLIMIT_AS, &limit) == 0;
  }
  ~AddressSpaceLimit() {
    if (active_) ::setrlimit(RLIMIT_AS, &saved_);
  }
  AddressSpaceLimit(const AddressSpaceLimit&) = delete;
  AddressSpaceLimit& operator=(const AddressSpaceLimit&) = delete;

 private:
  rlimit saved_{};
  bool active_ = false;
};

class FuzzRegression : public testing::TestWithParam<fuzz::Target> {};

TEST_P(FuzzRegression, EveryKeptInputIsAcceptedOrRefusedAsBadInput) {
  const fuzz::Target& target = GetParam();
  const std::filesystem::path root = test::sourceDir() / "tests" / "fuzz";
  const auto corpus = filesIn(root / "corpus" / target.name);
  const auto crashes = filesIn(root / "crashes" / target.name);
  // The seeds are committed: an empty corpus means a wrong path, not nothing to check.
  ASSERT_FALSE(corpus.empty()) << "no inputs in " << (root / "corpus" / target.name);
  size_t accepted = 0, refused = 0;
  const AddressSpaceLimit limit;
  for (const auto& files : {corpus, crashes})
    for (const auto& file : files) {
      const std::vector<uint8_t> bytes = bytesOf(file);
      try {
        target.entry(bytes);
        ++accepted;
      } catch (const InputError&) {
        ++refused;
      } catch (const std::exception& e) {
        ADD_FAILURE() << file << ": not bad input but " << e.what();
      }
    }
  RecordProperty("accepted", int(accepted));
  RecordProperty("refused", int(refused));
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzRegression, testing::ValuesIn(fuzz::kTargets),
                         [](const testing::TestParamInfo<fuzz::Target>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace glossy
