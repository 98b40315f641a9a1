// glTF scenes: the loader reads only from a path, so the bytes become a file (JSON or GLB, which the loader
// tells apart by content) in this process's folder, where any relative buffer URI is also looked for.
#include "renderer/scene/scene.h"
#include "tests/fuzz/fuzz_entries.h"
#include "tests/fuzz/fuzz_temp_dir.h"

namespace glossy::fuzz {

void gltfEntry(Bytes data) {
  const TempFile file("scene.gltf", data);
  (void)loadGltf(file.path());
}

}  // namespace glossy::fuzz
