// libFuzzer's entry for the target named by GLOSSY_FUZZ_TARGET (tests/fuzz/CMakeLists.txt). It catches
// exactly what the command line reports as bad input, InputError; any other exception escapes and libFuzzer
// records the input as a crash.
#include "materials/core/input_error.h"
#include "tests/fuzz/fuzz_entries.h"

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace {

constexpr auto entryOf(std::string_view name) {
  for (const auto& t : glossy::fuzz::kTargets)
    if (t.name == name) return t.entry;
  return static_cast<void (*)(glossy::fuzz::Bytes)>(nullptr);
}

constexpr auto kEntry = entryOf(GLOSSY_FUZZ_TARGET);
static_assert(kEntry != nullptr, "GLOSSY_FUZZ_TARGET names no entry of fuzz_entries.h");

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  try {
    kEntry({data, size});
  } catch (const glossy::InputError&) {
  }
  return 0;
}
