// The environment the command line names: --env FILE (lat-long .exr/.hdr), --env-constant V or R,G,B, or
// the built-in sky; --env-rotate turns maps and the sky about +Y. Shared by glossy render and glossy sheet.
#pragma once

#include "renderer/lights/environment.h"

#include <string>

namespace glossy::cli {

// InputError naming the option or the file for anything malformed.
Environment environmentFromOptions(const std::string& file, const std::string& constant, double rotateDegrees);

}  // namespace glossy::cli
