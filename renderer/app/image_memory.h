// The memory an image the command line is asked for will take, checked before any work: a sheet of seven
// 16384² panels would otherwise end in std::bad_alloc minutes into the run.
#pragma once

#include <string>

namespace glossy::app {

// Bytes per pixel the renderers hold, estimated from their buffers with room to spare: render's image,
// its accumulation and the EXR being written; a sheet panel's mean and four replicates (60), its error maps
// and the ꟻLIP images behind them (~40), the EXR's interleaved channels (144: grid, panels, two maps each),
// the PNG (~30) and the figures' per-pixel statistics.
inline constexpr double kRenderBytesPerPixel = 64.0;
inline constexpr double kSheetBytesPerPanelPixel = 320.0;

// InputError naming --width and --height and the size asked for when width × height × panels ×
// bytesPerPixel exceeds the machine's physical memory.
void checkImageMemory(int width, int height, int panels, double bytesPerPixel);

}  // namespace glossy::app
