// A Neural BRDF (Sztrajman, Rainer, Ritschel, Weyrich 2021): a small network fitted to one measured
// material (of MERL, RGL-EPFL or Nielsen 2015), a few kilobytes where a MERL table is 35 MB, so that the
// repository can carry measured data (materials/library/). The network maps Rusinkiewicz half/difference angles to RGB:
//   x = (sin θ_h, 0, cos θ_h, sin θ_d cos φ_d, sin θ_d sin φ_d, cos θ_d)      (φ_h = 0: isotropic)
//   ρ = exp(y) − 1,  y = dense layers of x (ReLU between them, linear last), in BRDF units (1/sr).
// The file format (.nbrdf, TOML) is in docs/measured.md; scripts/nbrdf-from-h5 makes it from the
// authors' Keras weights.
//
// glossy uses a network through tabulate(): the MERL table that the reconstructions in shared/merl were
// made by (shared/merl/SOURCES.md). Every lookup then reads that table with the reference nearest-bin
// lookup, as for MERL files (merl_table.h), so a sheet, a fit or an error from the network is the one from
// the reconstructed table, and rendering, fitting and sampling need nothing of their own.
#pragma once

#include "materials/core/types.h"
#include "materials/merl/merl_table.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace glossy {

class NeuralBrdf {
 public:
  static constexpr int kInputs = 6, kOutputs = 3;
  // The supplement's networks are 6 → 21 → 21 → 3: 675 weights and biases, 11 KB. Every load tabulates the
  // network 2.9 million times, so its cost is that count times the parameters: a network with more than
  // theirs is refused, from its layers' sizes, before any weight is read (a valid 11 MB network would
  // otherwise cost every command a thousand times a supplement network's load). A file over kMaxBytes is refused unread.
  static constexpr int kMaxParameters = 675;
  static constexpr int kMaxWidth = kMaxParameters / kOutputs;  // what a layer can have within the count
  static constexpr std::uintmax_t kMaxBytes = 256u << 10;

  // Throws InputError naming the file (and the line, for TOML errors) for a file that is missing, over
  // kMaxBytes, malformed, of another format or version, with a layer chain that does not go from 6 inputs to 3
  // outputs, more than kMaxParameters weights and biases, an unknown activation, arrays of the wrong length,
  // or a non-finite weight.
  static NeuralBrdf load(const std::filesystem::path& path);
  static NeuralBrdf parse(std::string_view text, const std::string& source);

  // The network's ρ at half/difference angles (radians), before any symmetrisation.
  Rgb evalAngles(double thetaH, double thetaD, double phiD) const;
  // The MERL table of shared/merl/SOURCES.md: at bin (i, j, k) the mean of the network at
  // θ_h = (i/90)² 90°, θ_d = j°, and φ_d = k° and k° + 180° (the lower bin edges, where the training
  // targets were the table's entries; the two φ_d the table folds together), clamped at 0, divided by the
  // channel scale and rounded to float. A bin whose centre has a direction below the horizon
  // (min(cos θ_i, cos θ_o) < −0.01) is unmeasured. Every load tabulates, so it is computed on all cores and
  // many bins side by side (AVX2 where the CPU has it), each value still exactly evalAngles's.
  MerlTable tabulate() const;

  const std::string& material() const { return material_; }
  // How results from the network are labelled, naming its database: "RGL-EPFL (NBRDF reconstruction)".
  const std::string& label() const { return label_; }
  const std::string& source() const { return source_; }  // the file, as given

 private:
  struct Layer {
    int inputs = 0, outputs = 0;
    bool relu = false;
    std::vector<double> weights;  // [input × outputs + output]
    std::vector<double> biases;
  };
  std::vector<Layer> layers_;
  std::string material_, label_, source_;
};

}  // namespace glossy
