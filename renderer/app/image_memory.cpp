#include "renderer/app/image_memory.h"

#include "materials/core/input_error.h"
#include "materials/core/text.h"
#include "renderer/util/memory.h"


namespace glossy::app {

namespace {

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

}  // namespace glossy::app
