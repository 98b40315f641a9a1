// The panel split of a sheet: its panels differ only in the BRDF of the object (RenderScene::objectMeshes),
// so a path is traced once up to its first vertex on the object, with that vertex's draws, light samples
// and shadow rays, none of which depends on the object's BRDF; from there each panel continues it with its
// own. A path that never meets the object is the same in every panel. The reference form is here; the
// wave stops and resumes its lanes the same way (wave_tracer.h).
#pragma once

#include "renderer/integrator/path_vertex.h"

namespace glossy {

// A path at its first vertex on the object, before the vertex's BRDF acts: all that the panels share.
struct ObjectVertex {
  int depth = 0;           // 0: the path never reached the object
  PathState path;
  Rgb radiance{0.0};       // gathered before the vertex
  PathVertex vertex;       // its point's brdf is the first panel's; each panel sets its own
  CmjSampler sampler;      // past the vertex's draws
};

// Li, but a path that reaches the object stops there (returning true, the radiance so far in
// vertex.radiance; vertex.depth is 0 when it did not stop); continueFromObject then finishes it for a
// panel, whose context differs only in the object's BRDF. The two make exactly Li's radiance.
bool traceToObject(const PathContext& context, Ray ray, CmjSampler& sampler, Rgb& radiance, ObjectVertex& stop);
Rgb continueFromObject(const PathContext& panel, ObjectVertex stop);

}  // namespace glossy
