// MERL tables. The reader accepts only the full 35 MB size, which no fuzzer input reaches, so the first byte
// picks the way in:
//   'N': the bytes as the start of a full-size file (header 90 × 90 × 180 and values, both of the fuzzer's
//        choosing where its bytes reach) whose remaining values are NaN: the header, size and value checks,
//        up to the first bad value, which is at the end of the fuzzer's bytes at the latest. A table that
//        reads whole takes 0.1–0.3 s under the sanitizers, a thousand times a refused one, and would take
//        most of the fuzzer's time: tests/merl_test.cpp reads whole tables;
//   any other even byte: the bytes as a whole .binary file (the header and size checks);
//   any other odd byte: the bytes as a .binary.xz file, asked for by its .binary name as a user would
//        (the xz decoder, then the checks).
// A table the reader accepts is looked up once.
#include "materials/merl/merl_table.h"
#include "tests/fuzz/fuzz_entries.h"
#include "tests/fuzz/fuzz_temp_dir.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace glossy::fuzz {

namespace {

// A full-size file of NaN values, overwritten at its start by one input and restored after it. Kept for
// the whole process: remaking 35 MB per input would be nearly all of an input's time.
class PaddedFile {
 public:
  PaddedFile() : bytes_(MerlTable::kFileBytes) { restore(bytes_.size()); }
  std::span<const std::byte> with(Bytes prefix) {
    used_ = std::min(prefix.size(), bytes_.size());
    std::memcpy(bytes_.data(), prefix.data(), used_);
    return bytes_;
  }
  void restore() { restore(used_); }

 private:
  void restore(size_t n) {
    const int32_t header[3] = {MerlTable::kThetaH, MerlTable::kThetaD, MerlTable::kPhiD};
    const double fill = std::numeric_limits<double>::quiet_NaN();
    std::memcpy(bytes_.data(), header, std::min(n, sizeof header));
    for (size_t at = sizeof header; at < n; at += sizeof fill) std::memcpy(bytes_.data() + at, &fill, sizeof fill);
    used_ = 0;
  }
  std::vector<std::byte> bytes_;
  size_t used_ = 0;
};

MerlTable parsePadded(Bytes prefix) {
  static PaddedFile padded;
  struct Restore {
    ~Restore() { padded.restore(); }
  } restore;
  return MerlTable::parse(padded.with(prefix), "fuzz.binary");
}

void use(const MerlTable& t) { (void)t.eval({0.3, 0.0, 0.953939201}, {-0.2, 0.1, 0.974679434}); }

}  // namespace

void merlEntry(Bytes data) {
  if (data.empty()) return;
  const Bytes rest = data.subspan(1);
  if (data[0] == 'N') {
    use(parsePadded(rest));
  } else if (data[0] % 2 == 0) {
    use(MerlTable::parse(std::as_bytes(rest), "fuzz.binary"));
  } else {
    const TempFile file("table.binary.xz", rest);
    use(MerlTable::load(file.path().parent_path() / "table.binary"));
  }
}

}  // namespace glossy::fuzz
