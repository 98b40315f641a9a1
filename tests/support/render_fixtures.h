// Scene pieces the renderer tests build in memory (a UV sphere, an orthographic camera looking down an
// axis, a lat-long map of small bright panels) and an independent reference for what a convex object under
// radiance 1 shows: the directional albedo.
#pragma once

#include "materials/models/brdf.h"
#include "renderer/scene/scene.h"

#include <glm/vec3.hpp>

#include <filesystem>
#include <vector>

namespace glossy::test {

// Two triangles from corner, facing edgeU × edgeV.
Mesh quad(glm::vec3 corner, glm::vec3 edgeU, glm::vec3 edgeV, int material);
// A scene material; an emission makes it a lamp.
SceneMaterial material(const char* name, Rgb baseColor = Rgb(0.8), Rgb emission = Rgb(0.0));
// The projected solid angle of a quad (corners in order) seen from p on a surface facing +Y, by Lambert's
// polygon formula: ½ |Σ_edges γ_i (ŷ · unit(v_i × v_{i+1}))|. An emitter's irradiance is Le times it.
double projectedSolidAngle(const glm::dvec3 (&corners)[4], const glm::dvec3& p);
// Unit-normal UV sphere of the given radius about the origin, counter-clockwise seen from outside.
Mesh uvSphere(double radius, int segments, int rings, int material);
// An orthographic camera at eye looking at target, half-extent halfExtent in both axes.
Camera orthographicDown(double halfExtent, glm::dvec3 eye, glm::dvec3 target, glm::dvec3 up);
// A perspective camera at eye looking at target (+Y up), yfov its vertical field of view.
Camera perspective(glm::dvec3 eye, glm::dvec3 target, double yfov);
// A glossy sphere (radius 1 about the origin, the given BRDF) on a Lambertian floor, and if asked a lamp
// (two emissive triangles 1.5 above the sphere's top, facing down onto it).
struct SphereOnFloor {
  SceneDescription description;
  std::vector<Brdf> brdfs;
  SphereOnFloor(const Brdf& sphere, bool lamp);
};
// A width × height lat-long map (float EXR at path) of small bright panels on a dim gradient: single
// texels, a 2 × 2 block and one on the top row (a pole), in three colours: where the light a sample of a
// cell finds varies most within the cell.
void writePanelsMap(const std::filesystem::path& path, int width, int height);
// ∫ρ(L,V) cos θ_L dω_L by a midpoint rule in (cos θ_L, φ_L) with nMu × nPhi points: independent of the
// renderer and of albedo.cpp, accurate for broad lobes and for tabulated (piecewise-constant) data.
Rgb directionalAlbedo(const Brdf& brdf, const Vec3& V, int nMu = 400, int nPhi = 800);

}  // namespace glossy::test
