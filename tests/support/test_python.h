// Running a reference script in the test-only Python (scripts/test-tools makes it) and exchanging raw
// float32 arrays with it: how the ꟻLIP and display-metric tests check glossy against independent packages.
#pragma once

#include "tests/support/test_support.h"

#include <filesystem>
#include <string>
#include <vector>

namespace glossy::test {

// The test Python's path; a test that needs it skips, saying so, where it is absent.
std::filesystem::path testPython();

struct ScriptRun {
  int status = -1;  // the exit status; -1 when the script did not exit normally
  std::string out, err;
};

// `script` (relative to the source tree) run with `args`, its stdout and stderr kept in `tmp`.
ScriptRun runTestPython(const TempDir& tmp, const std::string& script, const std::vector<std::string>& args);

void writeFloats(const std::filesystem::path& path, const std::vector<float>& values);
// Exactly `n` floats, or std::runtime_error naming the file.
std::vector<float> readFloats(const std::filesystem::path& path, size_t n);

}  // namespace glossy::test
