// Environment maps: OpenImageIO reads only from a path, and picks its reader by the extension, so the first
// byte chooses .exr or .hdr and the rest becomes that file. Loading builds the light's sampling
// distribution too, so every texel the loader accepts is used.
#include "renderer/lights/environment.h"
#include "tests/fuzz/fuzz_entries.h"
#include "tests/fuzz/fuzz_temp_dir.h"

namespace glossy::fuzz {

void envmapEntry(Bytes data) {
  if (data.empty()) return;
  const TempFile file(data[0] % 2 == 1 ? "map.exr" : "map.hdr", data.subspan(1));
  const Environment env = Environment::load(file.path());
  (void)env.radiance({0.0, 1.0, 0.0});
  (void)env.sample(Vec3(0.0), {0.3, 0.7});
  (void)env.sample(Vec3(0.0, 1.0, 0.0), {0.3, 0.7});
}

}  // namespace glossy::fuzz
