#include "materials/merl/merl_table.h"

#include "materials/core/input_error.h"
#include "materials/core/input_file.h"
#include "materials/core/text.h"

#include <lzma.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace glossy {

static_assert(std::endian::native == std::endian::little, "MERL files are little-endian; add byte swapping here");

namespace {

// The file's bytes. A .binary is exactly kFileBytes long (parse says how far off one is), and its .xz,
// however badly compressed, not much more: anything twice that is refused by its size, unread.
std::string readTableFile(const std::filesystem::path& path) {
  return readInputFile(path, 2 * MerlTable::kFileBytes, "MERL table");
}

// Decompresses an .xz stream; stops one byte past the size a MERL file may have, so a wrong file is
// reported as the wrong size without decompressing all of it. The output grows as it is produced, so that
// a file that is not xz, or a short one, costs what it holds rather than a table's 35 MB.
std::vector<std::byte> decompressXz(std::span<const std::byte> in, const std::string& source) {
  constexpr size_t kLimit = MerlTable::kFileBytes + 1;
  lzma_stream strm = LZMA_STREAM_INIT;
  // The decoder's memory follows the dictionary size the file declares (up to 1.5 GB); xz -9 needs 65 MB.
  constexpr uint64_t kMemoryLimit = uint64_t(256) << 20;
  if (lzma_stream_decoder(&strm, kMemoryLimit, 0) != LZMA_OK) throw InputError(source + ": cannot start xz decoder");
  std::vector<std::byte> out(std::min<size_t>(kLimit, 1 << 20));
  strm.next_in = reinterpret_cast<const uint8_t*>(in.data());
  strm.avail_in = in.size();
  lzma_ret ret = LZMA_OK;
  size_t produced = 0;
  while (ret == LZMA_OK) {
    if (produced == out.size()) {
      if (out.size() == kLimit) break;
      out.resize(std::min(kLimit, 2 * out.size()));
    }
    strm.next_out = reinterpret_cast<uint8_t*>(out.data() + produced);
    strm.avail_out = out.size() - produced;
    ret = lzma_code(&strm, LZMA_FINISH);
    produced = out.size() - strm.avail_out;
  }
  lzma_end(&strm);
  if (ret != LZMA_STREAM_END && !(ret == LZMA_OK && produced == kLimit)) {
    const char* why = ret == LZMA_FORMAT_ERROR ? "not an xz file"
                      : ret == LZMA_DATA_ERROR ? "corrupt xz data"
                      : ret == LZMA_BUF_ERROR  ? "truncated xz data"
                      : ret == LZMA_MEMLIMIT_ERROR ? "xz data that needs over 256 MB to decompress"
                                               : "xz decoding failed";
    throw InputError(source + ": " + why);
  }
  out.resize(produced);
  return out;
}

int clampBin(double x, int n) { return std::clamp(static_cast<int>(std::floor(x)), 0, n - 1); }

}  // namespace

size_t MerlBin::index() const {
  return size_t(phiD) + size_t(MerlTable::kPhiD) * (size_t(thetaD) + size_t(MerlTable::kThetaD) * size_t(thetaH));
}

MerlTable MerlTable::load(const std::filesystem::path& requested) {
  // Users often keep the database compressed: NAME.binary.xz stands in for an absent NAME.binary.
  std::filesystem::path path = requested;
  std::error_code ec;
  if (!std::filesystem::exists(path, ec) && path.extension() != ".xz") {
    const std::filesystem::path xz = path.string() + ".xz";
    if (std::filesystem::exists(xz, ec)) path = xz;
  }
  const std::string file = readTableFile(path);
  const std::span<const std::byte> bytes = std::as_bytes(std::span(file));
  if (path.extension() == ".xz") return parse(decompressXz(bytes, path.string()), path.string());
  return parse(bytes, path.string());
}

MerlTable MerlTable::parse(std::span<const std::byte> bytes, const std::string& source) {
  if (bytes.size() < 3 * sizeof(int32_t))
    throw InputError(source + ": truncated MERL file (" + std::to_string(bytes.size()) + " bytes, expected " +
                     std::to_string(kFileBytes) + ")");
  int32_t dims[3];
  std::memcpy(dims, bytes.data(), sizeof dims);
  if (dims[0] != kThetaH || dims[1] != kThetaD || dims[2] != kPhiD)
    throw InputError(source + ": not a MERL BRDF (header " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) +
                     "x" + std::to_string(dims[2]) + ", expected 90x90x180)");
  if (bytes.size() != kFileBytes)
    throw InputError(source + ": " + (bytes.size() < kFileBytes ? "truncated" : "oversized") + " MERL file (" +
                     std::to_string(bytes.size()) + " bytes, expected " + std::to_string(kFileBytes) + ")");

  // Read in place (unaligned, hence memcpy): a copy of the values would be another 35 MB.
  const std::byte* data = bytes.data() + sizeof dims;
  return build(
      [data](size_t k) {
        double v;
        std::memcpy(&v, data + k * sizeof v, sizeof v);
        return v;
      },
      source);
}

MerlTable MerlTable::fromValues(std::span<const double> values, const std::string& source) {
  if (values.size() != 3 * kBins) throw InputError(source + ": " + std::to_string(values.size()) + " values, expected 3 × 1458000");
  return build([values](size_t k) { return values[k]; }, source);
}

template <class ValueAt>
MerlTable MerlTable::build(const ValueAt& valueAt, const std::string& source) {
  // Every value is checked before the table is allocated: a bad file costs only the reading up to its
  // first bad value.
  for (int c = 0; c < 3; ++c) {
    for (size_t i = 0; i < kBins; ++i) {
      const double v = valueAt(c * kBins + i);
      if (std::isfinite(v) && v * kScale[c] <= kMaxValue) continue;
      const int iph = int(i % kPhiD), itd = int(i / kPhiD % kThetaD), ith = int(i / (size_t(kPhiD) * kThetaD));
      const std::string bin = std::string(" in channel ") + "RGB"[c] + " at bin (θh " + std::to_string(ith) + ", θd " +
                              std::to_string(itd) + ", φd " + std::to_string(iph) + ")";
      if (!std::isfinite(v)) throw InputError(source + ": non-finite value" + bin);
      throw InputError(source + ": value " + formatted("%.6g", v * kScale[c]) + " /sr" + bin + " is above the plausible maximum " +
                       formatted("%g", kMaxValue) + " /sr of a measured BRDF");
    }
  }
  MerlTable t;
  t.source_ = source;
  t.raw_.assign(3 * kBins, 0.0f);
  t.valid_.assign(kBins, 1);
  for (int c = 0; c < 3; ++c) {
    for (size_t i = 0; i < kBins; ++i) {
      const double v = valueAt(c * kBins + i);
      if (v < 0.0) t.valid_[i] = 0;
      t.raw_[3 * i + c] = static_cast<float>(v);
    }
  }
  for (size_t i = 0; i < kBins; ++i) {
    if (t.valid_[i]) continue;
    ++t.invalidBins_;
    t.raw_[3 * i] = t.raw_[3 * i + 1] = t.raw_[3 * i + 2] = 0.0f;
  }
  return t;
}

MerlBin MerlTable::binOf(const Vec3& L, const Vec3& V) {
  const Vec3 h = L + V;
  const double hl = std::sqrt(h.x * h.x + h.y * h.y + h.z * h.z);
  const Vec3 H = h / hl;
  const double thetaH = std::acos(std::clamp(H.z, -1.0, 1.0));
  const double phiH = std::atan2(H.y, H.x);
  // D = L rotated about z by −φ_h, then about y by −θ_h.
  const double cp = std::cos(phiH), sp = std::sin(phiH);
  const double x1 = L.x * cp + L.y * sp, y1 = -L.x * sp + L.y * cp, z1 = L.z;
  const double ct = std::cos(thetaH), st = std::sin(thetaH);
  const double dx = x1 * ct - z1 * st, dy = y1, dz = x1 * st + z1 * ct;
  const double thetaD = std::acos(std::clamp(dz, -1.0, 1.0));
  double phiD = std::atan2(dy, dx);
  if (phiD < 0.0) phiD += kPi;  // reciprocity fold

  MerlBin bin;
  bin.thetaH = thetaH <= 0.0 ? 0 : clampBin(kThetaH * std::sqrt(thetaH / (kPi / 2.0)), kThetaH);
  bin.thetaD = clampBin(thetaD / (kPi / 2.0) * kThetaD, kThetaD);
  bin.phiD = clampBin(phiD / kPi * kPhiD, kPhiD);
  return bin;
}

Rgb MerlTable::value(size_t i) const {
  return {raw_[3 * i] * kScale[0], raw_[3 * i + 1] * kScale[1], raw_[3 * i + 2] * kScale[2]};
}

Rgb MerlTable::eval(const Vec3& L, const Vec3& V) const {
  if (L.z <= 0.0 || V.z <= 0.0) return Rgb(0.0);
  return value(binOf(L, V).index());
}

}  // namespace glossy
