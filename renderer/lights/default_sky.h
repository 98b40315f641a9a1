// The built-in environment: a procedural studio sky generated here, so a render needs no downloaded map.
#pragma once

#include "renderer/lights/latlong.h"

namespace glossy {

// A 1024 × 512 lat-long map (spec convention): blue-grey sky gradient, a warm soft-edged sun high in the
// front-right quadrant (direction ≈ (+X, +Y, +Z)), two dimmer rectangular softboxes (a fill at front-left,
// a rim strip behind) and a darker neutral ground. Scaled so a grey Lambertian object renders at about
// 0.3–0.8 of its albedo without tone mapping.
LatLongImage makeDefaultSky();

}  // namespace glossy
