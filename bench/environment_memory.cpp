// Peak memory of loading an environment map, per texel: the resident set's peak (getrusage) above what
// the process held before the load, over W × H. Prints figures, asserts nothing. Run one map per process,
// as the peak is the process's. The target is 20 bytes per texel (16 for the RGB + cell-value texels the
// light keeps, about 2 for its sampling tables, and what reading the file costs on top).
#include "renderer/lights/environment.h"

#include <OpenImageIO/imageio.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <string>
#include <sys/resource.h>

namespace {

double residentBytes() {  // now, from /proc (pages × page size)
  std::ifstream statm("/proc/self/statm");
  long size = 0, resident = 0;
  statm >> size >> resident;
  return double(resident) * 4096.0;
}

double peakBytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) * 1024.0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: environment_memory MAP.(hdr|exr)\n");
    return 2;
  }
  // OpenImageIO's plugins and the allocator's arenas are loaded before the baseline is taken.
  { auto probe = OIIO::ImageInput::open(argv[1]); }
  const double before = residentBytes();
  const auto start = std::chrono::steady_clock::now();
  const glossy::Environment environment = glossy::Environment::load(argv[1]);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  auto in = OIIO::ImageInput::open(argv[1]);
  const double texels = double(in->spec().width) * double(in->spec().height);
  std::printf("%s: %d x %d, load %.2f s, peak %.1f bytes/texel (%.0f MB above the baseline), resident after %.1f bytes/texel\n",
              argv[1], in->spec().width, in->spec().height, seconds, (peakBytes() - before) / texels,
              (peakBytes() - before) / 1e6, (residentBytes() - before) / texels);
  return 0;
}
