// Where the program's own files are: the default scene (scenes/), the material library (materials/library/). The
// source tree the program was built from, unless a packaged copy says otherwise (the Python module's
// wheel carries them in glossy/data and sets it on import).
#pragma once

#include <filesystem>

namespace glossy {

std::filesystem::path dataDir();
// The material library: the working folder's materials/library when it is a checkout's (a relative path, as
// the user would write it), else the one in dataDir().
std::filesystem::path materialLibraryDir();
// Not synchronised with readers: set it before anything loads a scene.
void setDataDir(std::filesystem::path dir);

}  // namespace glossy
