// The machine's physical memory, against which sizes asked for by input (an image, an environment map)
// are checked before allocating: refusing with the size is better than std::bad_alloc or the OOM killer.
#pragma once

namespace glossy {

// Bytes of physical memory, or 0 where the system does not say.
double physicalMemoryBytes();

}  // namespace glossy
