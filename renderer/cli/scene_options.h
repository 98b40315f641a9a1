// What glossy render and glossy sheet take from the command line about the scene: the environment and the
// camera.
#pragma once

#include "renderer/lights/environment.h"
#include "renderer/scene/scene.h"

#include <string>

namespace glossy::cli {

// --env FILE (lat-long .exr/.hdr), --env-constant V or R,G,B, or the built-in sky; --env-rotate turns maps
// and the sky about +Y. InputError naming the option or the file for anything malformed.
Environment environmentFromOptions(const std::string& file, const std::string& constant, double rotateDegrees);

// --camera NAME, or the scene's first camera; InputError naming the scene when there is none.
const Camera& cameraFromOptions(const SceneDescription& scene, const std::string& name, const std::string& scenePath);

}  // namespace glossy::cli
