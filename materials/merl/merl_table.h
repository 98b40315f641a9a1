// A MERL measured BRDF table (Matusik et al. 2003): 90 θ_h × 90 θ_d × 180 φ_d bins over Rusinkiewicz
// half/difference coordinates, isotropic. The reference nearest-lower-bin lookup of shared/spec/merl.md
// is the one used everywhere (rendering, fitting, eval), so that all of them see the same data.
#pragma once

#include "materials/core/types.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace glossy {

struct MerlBin {
  int thetaH, thetaD, phiD;
  size_t index() const;  // i_φd + 180 (i_θd + 90 i_θh)
};

class MerlTable {
 public:
  static constexpr int kThetaH = 90, kThetaD = 90, kPhiD = 180;
  static constexpr size_t kBins = size_t(kThetaH) * kThetaD * kPhiD;  // 1,458,000
  static constexpr size_t kFileBytes = 3 * sizeof(int32_t) + 3 * kBins * sizeof(double);  // 34,992,012
  // The reference reader's per-channel scale to BRDF units.
  static constexpr double kScale[3] = {1.0 / 1500.0, 1.15 / 1500.0, 1.66 / 1500.0};
  // The largest scaled value (1/sr) a table may hold. The published fits' peaks are a few 1e4, and tables
  // tabulated from the sharpest lobes the parameter ranges accept reach some 1e6 at grazing angles; far
  // above that a file is corrupt, and values near float's range (stored values are float) overflow the
  // sampling tables' sums into Inf or NaN. At 1e10 those sums stay well inside float.
  static constexpr double kMaxValue = 1e10;

  // Reads NAME.binary, or NAME.binary.xz (decompressed in memory). Throws InputError naming the file for
  // a wrong size, header, truncated or unreadable file, or a non-finite value or one above kMaxValue.
  static MerlTable load(const std::filesystem::path& path);
  // Parses the bytes of a .binary file; `source` names it in errors.
  static MerlTable parse(std::span<const std::byte> bytes, const std::string& source);
  // The table of these values, unscaled and in the file's order (the R block, then G, then B, each
  // 3 × kBins long in all; negative: unmeasured). Throws InputError naming `source` and the bin for a
  // non-finite one or one above kMaxValue once scaled.
  static MerlTable fromValues(std::span<const double> values, const std::string& source);

  // ρ(L, V) in BRDF units (1/sr); 0 below the horizon and in unmeasured bins.
  Rgb eval(const Vec3& L, const Vec3& V) const;
  // The bin the reference lookup picks for (L, V), both unit vectors with L_z, V_z > 0.
  static MerlBin binOf(const Vec3& L, const Vec3& V);

  Rgb value(size_t binIndex) const;   // scaled; 0 for an invalid bin
  bool valid(size_t binIndex) const { return valid_[binIndex] != 0; }
  size_t invalidBins() const { return invalidBins_; }
  const std::string& source() const { return source_; }

 private:
  // The table of the values valueAt(k), k < 3 × kBins, in the file's order: fromValues's, for any source.
  template <class ValueAt>
  static MerlTable build(const ValueAt& valueAt, const std::string& source);

  std::vector<float> raw_;       // unscaled stored values, RGB interleaved per bin; invalid bins hold 0
  std::vector<uint8_t> valid_;   // 1 where all three channels were measured (non-negative)
  size_t invalidBins_ = 0;
  std::string source_;
};

}  // namespace glossy
