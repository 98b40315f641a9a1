// What a render or a sheet is told about the scene: the glTF file, the camera and the environment
// (glossy render and sheet: --scene, --camera, --env, --env-constant, --env-rotate).
#pragma once

#include "renderer/lights/environment.h"
#include "renderer/scene/scene.h"

#include <string>

namespace glossy::app {

struct SceneOptions {
  std::string scene, camera, env, envConstant;
  double envRotate = 0.0;

  std::string scenePath() const;  // --scene, else the source tree's scenes/preview.gltf
  // --env FILE (lat-long .exr/.hdr), --env-constant V or R,G,B, or the built-in sky; --env-rotate turns maps
  // and the sky about +Y. InputError naming the option or the file for anything malformed.
  Environment environment() const;
  // --camera NAME, or the scene's first camera; --camera auto, or a scene without cameras: autoCamera
  // framing the bound object for an image of width / height `aspect` (a scene without cameras says so on
  // stderr). InputError naming the scene when no camera has the name.
  Camera cameraOf(const SceneDescription& description, double aspect) const;
};

}  // namespace glossy::app
