// The scene's meshes as Embree 3 triangle geometries (geomID = mesh index) in one high-quality BVH, and
// the two queries the renderer needs. Hit geometry is recomputed in double from the mesh data, so normals
// do not inherit Embree's float rounding or its (clockwise) normal convention.
#include "renderer/scene/embree_scene.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <stdexcept>

namespace glossy {

namespace {

std::mutex embreeErrorMutex;

// Embree reports errors through this callback (possibly from its build threads); throwing from inside
// Embree's C API is not allowed, so the first message is kept and thrown after the call returns.
void recordEmbreeError(void* userPtr, RTCError code, const char* message) {
  auto& error = *static_cast<std::string*>(userPtr);
  const std::lock_guard<std::mutex> lock(embreeErrorMutex);
  if (error.empty())
    error = message && *message ? std::string(message) : "error code " + std::to_string(int(code));
}

}  // namespace

RTCRay toRtcRay(const Ray& ray) {
  constexpr float kMax = std::numeric_limits<float>::max(), kInf = std::numeric_limits<float>::infinity();
  return {.org_x = float(ray.origin.x), .org_y = float(ray.origin.y), .org_z = float(ray.origin.z),
          .tnear = float(std::max(ray.tnear, 0.0)),
          .dir_x = float(ray.dir.x), .dir_y = float(ray.dir.y), .dir_z = float(ray.dir.z),
          .time = 0.0f,
          .tfar = ray.tfar >= double(kMax) ? kInf : float(ray.tfar),
          .mask = ~0u, .id = 0, .flags = 0};
}

EmbreeScene::EmbreeScene(const SceneDescription& scene) : scene_(scene) {
  try {
    device_ = rtcNewDevice(nullptr);
    if (!device_)
      throw std::runtime_error("Embree: cannot create a device (error code " +
                               std::to_string(int(rtcGetDeviceError(nullptr))) + ")");
    rtcSetDeviceErrorFunction(device_, recordEmbreeError, &embreeError_);
    rtcScene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(rtcScene_, RTC_BUILD_QUALITY_HIGH);
    throwIfEmbreeFailed("creating the scene");

    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (size_t m = 0; m < scene.meshes.size(); ++m) {
      const Mesh& mesh = scene.meshes[m];
      // Embree reads indices unchecked: a bad mesh built in code must not become an out-of-bounds read.
      if (mesh.indices.size() % 3 != 0 ||
          std::any_of(mesh.indices.begin(), mesh.indices.end(), [&](uint32_t i) { return i >= mesh.positions.size(); }) ||
          (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()))
        throw std::runtime_error("Embree scene: " + mesh.name + ": inconsistent indices or normals");
      if (mesh.indices.empty()) continue;

      RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
      auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                                   RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                                   mesh.positions.size()));
      auto* triangles = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
                                                                      RTC_FORMAT_UINT3, 3 * sizeof(uint32_t),
                                                                      mesh.indices.size() / 3));
      if (vertices && triangles) {
        std::memcpy(vertices, mesh.positions.data(), mesh.positions.size() * 3 * sizeof(float));
        std::memcpy(triangles, mesh.indices.data(), mesh.indices.size() * sizeof(uint32_t));
        rtcCommitGeometry(geometry);
        rtcAttachGeometryByID(rtcScene_, geometry, unsigned(m));
      }
      rtcReleaseGeometry(geometry);
      throwIfEmbreeFailed("adding a mesh");

      for (const glm::vec3& p : mesh.positions) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
      }
    }
    rtcCommitScene(rtcScene_);
    throwIfEmbreeFailed("building the BVH");

    if (lo.x <= hi.x) {
      center_ = (Vec3(lo) + Vec3(hi)) * 0.5;
      for (const Mesh& mesh : scene.meshes)
        for (const glm::vec3& p : mesh.positions) radius_ = std::max(radius_, glm::distance(center_, Vec3(p)));
    }
  } catch (...) {
    release();
    throw;
  }
}

EmbreeScene::~EmbreeScene() { release(); }

void EmbreeScene::release() {
  if (rtcScene_) rtcReleaseScene(rtcScene_);
  if (device_) rtcReleaseDevice(device_);
  rtcScene_ = nullptr;
  device_ = nullptr;
}

void EmbreeScene::throwIfEmbreeFailed(const char* doing) const {
  const std::lock_guard<std::mutex> lock(embreeErrorMutex);
  if (!embreeError_.empty()) throw std::runtime_error(std::string("Embree error while ") + doing + ": " + embreeError_);
}

bool EmbreeScene::intersect(const Ray& ray, Hit& hit) const {
  if (recorder_) [[unlikely]]
    recorder_->record(ray, false);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit;
  rayHit.ray = toRtcRay(ray);
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(rtcScene_, &context, &rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return false;
  hit = completeHit(ray, rayHit.hit.geomID, rayHit.hit.primID, rayHit.ray.tfar, rayHit.hit.u, rayHit.hit.v);
  return true;
}

Hit EmbreeScene::completeHit(const Ray& ray, uint32_t meshIndex, uint32_t triangle, double t, double u, double v) const {
  Hit hit{.t = t, .mesh = meshIndex, .triangle = triangle, .u = u, .v = v};
  const Mesh& mesh = scene_.meshes[meshIndex];
  const uint32_t* corner = &mesh.indices[3 * size_t(hit.triangle)];
  const Vec3 p0(mesh.positions[corner[0]]), p1(mesh.positions[corner[1]]), p2(mesh.positions[corner[2]]);
  // The ray against the triangle again, in double (Möller–Trumbore): Embree's float t, u, v depend on
  // which of its kernels answered, these only on the ray and the triangle. The point is formed from the
  // barycentrics, so it lies on the triangle's plane to double precision.
  const Vec3 e1 = p1 - p0, e2 = p2 - p0, pv = glm::cross(ray.dir, e2);
  const double det = glm::dot(e1, pv);
  if (det != 0.0) {
    const Vec3 tv = ray.origin - p0, qv = glm::cross(tv, e1);
    hit.u = glm::dot(tv, pv) / det;
    hit.v = glm::dot(ray.dir, qv) / det;
    hit.t = glm::dot(e2, qv) / det;
  }
  hit.position = (1.0 - hit.u - hit.v) * p0 + hit.u * p1 + hit.v * p2;
  hit.margin = triangleMargin(p0, p1, p2);
  hit.geometricNormal = glm::normalize(glm::cross(e1, e2));
  hit.shadingNormal = hit.geometricNormal;
  if (!mesh.normals.empty()) {
    const Vec3 n = (1.0 - hit.u - hit.v) * Vec3(mesh.normals[corner[0]]) + hit.u * Vec3(mesh.normals[corner[1]]) +
                   hit.v * Vec3(mesh.normals[corner[2]]);
    const double len = glm::length(n);
    if (len > 1e-12 && std::isfinite(len)) hit.shadingNormal = n / len;
  }
  return hit;
}

void EmbreeScene::intersect(const bool* valid, const Ray* rays, Hit* hits, bool* found, int n) const {
  for (int p = 0; p < n; p += kPacketSize) intersectPacket(valid + p, rays + p, hits + p, found + p);
}

void EmbreeScene::occluded(const bool* valid, const Ray* rays, bool* occluded, int n) const {
  for (int p = 0; p < n; p += kPacketSize) occludedPacket(valid + p, rays + p, occluded + p);
}

void EmbreeScene::intersectPacket(const bool* valid, const Ray* rays, Hit* hits, bool* found) const {
  if (recorder_) [[unlikely]]
    recorder_->recordPacket(rays, valid, false);
  alignas(32) int mask[kPacketSize];
  alignas(32) RTCRayHit8 packet;
  for (int i = 0; i < kPacketSize; ++i) {
    const RTCRay ray = valid[i] ? toRtcRay(rays[i]) : RTCRay{};
    setPacketHitLane(packet, mask, i, valid[i] ? &ray : nullptr);
  }
  if (std::none_of(valid, valid + kPacketSize, [](bool v) { return v; })) return;
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcIntersect8(mask, rtcScene_, &context, &packet);
  for (int i = 0; i < kPacketSize; ++i) {
    if (!valid[i]) continue;
    found[i] = packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID;
    if (found[i])
      hits[i] = completeHit(rays[i], packet.hit.geomID[i], packet.hit.primID[i], packet.ray.tfar[i], packet.hit.u[i], packet.hit.v[i]);
  }
}

void EmbreeScene::occludedPacket(const bool* valid, const Ray* rays, bool* occluded) const {
  alignas(32) int mask[kPacketSize];
  alignas(32) RTCRay8 packet;
  bool traced[kPacketSize], any = false;
  for (int i = 0; i < kPacketSize; ++i) {
    // The same empty-segment rule as the one-ray query.
    traced[i] = valid[i] && rays[i].tfar >= rays[i].tnear;
    mask[i] = traced[i] ? -1 : 0;
    if (valid[i]) occluded[i] = false;
    if (!traced[i]) continue;
    any = true;
    setPacketLane(packet, i, toRtcRay(rays[i]));
  }
  if (!any) return;
  if (recorder_) [[unlikely]]
    recorder_->recordPacket(rays, traced, true);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  rtcOccluded8(mask, rtcScene_, &context, &packet);
  for (int i = 0; i < kPacketSize; ++i)
    if (traced[i]) occluded[i] = packet.tfar[i] == -std::numeric_limits<float>::infinity();
}

bool EmbreeScene::occluded(const Ray& ray) const {
  if (!(ray.tfar >= ray.tnear)) return false;
  if (recorder_) [[unlikely]]
    recorder_->record(ray, true);
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay r = toRtcRay(ray);
  rtcOccluded1(rtcScene_, &context, &r);
  // Embree marks an occluded ray by setting tfar to −∞.
  return r.tfar == -std::numeric_limits<float>::infinity();
}

}  // namespace glossy
