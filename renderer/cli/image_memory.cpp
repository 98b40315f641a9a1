#include "renderer/cli/image_memory.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"

#include <unistd.h>

namespace glossy::cli {

namespace {

double physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  return pages > 0 && pageSize > 0 ? double(pages) * double(pageSize) : 0.0;
}

std::string gigabytes(double bytes) { return formatted("%.3g GB", bytes / 1e9); }

}  // namespace

void checkImageMemory(int width, int height, int panels, double bytesPerPixel) {
  const double need = double(width) * double(height) * double(panels) * bytesPerPixel;
  const double have = physicalMemoryBytes();
  if (have <= 0.0 || need <= have) return;
  const std::string what = panels > 1 ? formatted(" x %d panels", panels) : std::string();
  throw InputError(formatted("--width %d --height %d", width, height) + ": " + formatted("%dx%d", width, height) + what +
                   " needs about " + gigabytes(need) + ", more than the " + gigabytes(have) + " of memory here");
}

}  // namespace glossy::cli
