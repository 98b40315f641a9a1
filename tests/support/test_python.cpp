#include "tests/support/test_python.h"

#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <sys/wait.h>

namespace glossy::test {

std::filesystem::path testPython() { return GLOSSY_TEST_PYTHON; }

ScriptRun runTestPython(const TempDir& tmp, const std::string& script, const std::vector<std::string>& args) {
  std::string cmd = shellQuote(testPython().string());
  cmd.append(" ").append(shellQuote((sourceDir() / script).string()));
  for (const auto& a : args) cmd.append(" ").append(shellQuote(a));
  cmd.append(" >").append(shellQuote((tmp / "script.out").string()));
  cmd.append(" 2>").append(shellQuote((tmp / "script.err").string()));
  const int raw = std::system(cmd.c_str());
  ScriptRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = readText(tmp / "script.out");
  r.err = readText(tmp / "script.err");
  return r;
}

void writeFloats(const std::filesystem::path& path, const std::vector<float>& values) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(values.data()), std::streamsize(values.size() * sizeof(float)));
  if (!out) throw std::runtime_error("cannot write " + path.string());
}

std::vector<float> readFloats(const std::filesystem::path& path, size_t n) {
  std::vector<float> v(n);
  std::ifstream in(path, std::ios::binary);
  in.read(reinterpret_cast<char*>(v.data()), std::streamsize(n * sizeof(float)));
  if (!in) throw std::runtime_error("cannot read " + path.string());
  return v;
}

}  // namespace glossy::test
