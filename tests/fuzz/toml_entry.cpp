// The two TOML formats: material parameter files and Neural BRDF networks. Parsed from memory (the file
// loaders only read the whole file into a string first), then used as the program would: every fit of a
// material made into its BRDF and evaluated and sampled once, a network evaluated at a few angles.
#include "materials/models/brdf.h"
#include "materials/nbrdf/neural_brdf.h"
#include "materials/params/material_file.h"
#include "tests/fuzz/fuzz_entries.h"

#include <string_view>

namespace glossy::fuzz {

void tomlEntry(Bytes data) {
  if (data.empty()) return;
  const std::string_view text(reinterpret_cast<const char*>(data.data()) + 1, data.size() - 1);
  if (data[0] % 2 == 1) {
    const MaterialFile m = parseMaterialToml(text, "fuzz.toml");
    const Vec3 L{0.3, 0.0, 0.953939201}, V{-0.2, 0.1, 0.974679434};
    for (const Fit& fit : m.fits) {
      const Brdf brdf = makeBrdf(fit);
      (void)eval(brdf, L, V);
      (void)pdf(brdf, L, V);
      (void)sample(brdf, V, 0.37, {0.61, 0.23});
    }
  } else {
    const NeuralBrdf n = NeuralBrdf::parse(text, "fuzz.nbrdf");
    for (double theta : {0.0, 0.7, 1.5}) (void)n.evalAngles(theta, 0.5 * theta, 2.0 * theta);
  }
}

}  // namespace glossy::fuzz
