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
  // Everything an image takes from these options, as the start of a sheet's settings line (sheet_resume.h):
  // the scene's path and the lighting's description (what the report shows), then what those leave out —
  // a digest of the contents of the scene (`scene`, loaded from scenePath(), carries it) and of the map, the
  // camera, and each number at full precision — so that a map or scene edited in place, another folder's
  // map of the same name, or a rotation changed in its seventh digit reads as other settings.
  // `environment`: environment()'s. InputError naming the map if it cannot be read.
  std::string inputs(const SceneDescription& scene, const Environment& environment) const;
};

}  // namespace glossy::app
