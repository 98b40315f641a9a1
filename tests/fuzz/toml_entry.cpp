// Material parameter files. Parsed from memory (the file loader only reads the whole file into a string
// first), then used as the program would: every fit made into its BRDF and evaluated and sampled once, and
// looked up by its name as --fit and the sheets look fits up.
#include "materials/models/brdf.h"
#include "materials/params/material_file.h"
#include "tests/fuzz/fuzz_entries.h"

#include <stdexcept>
#include <string_view>

namespace glossy::fuzz {

void tomlEntry(Bytes data) {
  const std::string_view text(reinterpret_cast<const char*>(data.data()), data.size());
  const MaterialFile m = parseMaterialToml(text, "fuzz.toml");
  const Vec3 L{0.3, 0.0, 0.953939201}, V{-0.2, 0.1, 0.974679434};
  for (const Fit& fit : m.fits) {
    if (m.find(FitId::parse(fit.id.str(), "fuzz")) == nullptr) throw std::logic_error("a loaded fit not found by its name");
    const Brdf brdf = makeBrdf(fit);
    (void)eval(brdf, L, V);
    (void)pdf(brdf, L, V);
    (void)sample(brdf, V, 0.37, {0.61, 0.23});
  }
  (void)toToml(m);
}

}  // namespace glossy::fuzz
