// Neural BRDF networks (.nbrdf, TOML): parsed from memory (NeuralBrdf::load only reads the whole file into
// a string first, after checking its size), then evaluated at a few angles, through every layer.
#include "materials/nbrdf/neural_brdf.h"
#include "tests/fuzz/fuzz_entries.h"

#include <string_view>

namespace glossy::fuzz {

void nbrdfEntry(Bytes data) {
  const std::string_view text(reinterpret_cast<const char*>(data.data()), data.size());
  const NeuralBrdf n = NeuralBrdf::parse(text, "fuzz.nbrdf");
  for (double theta : {0.0, 0.7, 1.5}) (void)n.evalAngles(theta, 0.5 * theta, 2.0 * theta);
}

}  // namespace glossy::fuzz
