// The camera glossy frames a scene with when the file has none (most real models) or --camera auto asks
// for it: the material-preview scene's view (scenes/preview.gltf: 30° vertical field of view, looking 7.24°
// down), aimed at the centre of the bound object's bounding sphere (the meshes whose material binds a glossy
// material; every mesh when none does) from the distance at which the sphere just fits the frame.
#pragma once

#include "renderer/scene/scene.h"

namespace glossy {

// `aspect` is the image's width / height: the sphere fits the narrower of the two fields of view. Throws
// InputError naming the scene when it is too large to frame within kMaxSceneCoordinate.
Camera autoCamera(const SceneDescription& scene, double aspect = 1.0);

}  // namespace glossy
