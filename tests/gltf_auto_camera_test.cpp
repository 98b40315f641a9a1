// The automatic camera (--camera auto, and scenes without a camera): the preview scene's view, centred on
// the bound object, which fills a sensible part of the frame.
#include "materials/core/input_error.h"
#include "renderer/camera/auto_camera.h"
#include "renderer/image/exr_image.h"
#include "renderer/scene/scene.h"
#include "tests/support/gltf_doc.h"
#include "tests/support/test_support.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>

namespace glossy::test {

namespace {

using nlohmann::json;

Vec3 forwardOf(const Camera& c) { return glm::normalize(Vec3(c.cameraToWorld * glm::dvec4(0, 0, -1, 0))); }

// The image-plane box of a mesh's vertices as the camera sees them, in [-1, 1]² at the frame's edges.
struct Projection {
  glm::dvec2 lo{INFINITY}, hi{-INFINITY};
  glm::dvec2 centre() const { return 0.5 * (lo + hi); }
};
Projection project(const Camera& c, const std::vector<Mesh>& meshes, double aspect) {
  const glm::dmat4 worldToCamera = glm::inverse(c.cameraToWorld);
  const double t = std::tan(0.5 * c.yfov);
  Projection p;
  for (const Mesh& m : meshes)
    for (const glm::vec3& v : m.positions) {
      const Vec3 q(worldToCamera * glm::dvec4(Vec3(v), 1.0));
      EXPECT_LT(q.z, 0.0) << "a vertex behind the camera";
      const glm::dvec2 s(q.x / (-q.z) / (t * aspect), q.y / (-q.z) / t);
      p.lo = glm::min(p.lo, s);
      p.hi = glm::max(p.hi, s);
    }
  return p;
}

// One box, off the origin, and no camera.
GltfDoc lonelyBox() {
  GltfDoc g;
  g.setScene({g.addMeshNode("Box", boxPrimitive(g, {5, 2, -3}, {2, 1, 0.5}))});
  return g;
}

}  // namespace

TEST(GltfAutoCamera, HasThePreviewScenesDirectionAndFieldOfView) {
  const SceneDescription preview = loadGltf(sourceDir() / "scenes/preview.gltf");
  ASSERT_FALSE(preview.cameras.empty());
  TempDir dir;
  const SceneDescription s = loadGltf(lonelyBox().writeExternal(dir, "box"));
  const Camera c = autoCamera(s);
  EXPECT_EQ(c.type, Camera::Type::Perspective);
  EXPECT_DOUBLE_EQ(c.yfov, preview.cameras[0].yfov);
  const Vec3 a = forwardOf(c), b = forwardOf(preview.cameras[0]);
  EXPECT_NEAR(glm::dot(a, b), 1.0, 1e-12);
}

TEST(GltfAutoCamera, CentresAndFillsTheFrame) {
  TempDir dir;
  const SceneDescription s = loadGltf(lonelyBox().writeExternal(dir, "box"));
  for (double aspect : {1.0, 2.0, 0.5}) {
    SCOPED_TRACE(aspect);
    const Projection p = project(autoCamera(s, aspect), s.meshes, aspect);
    EXPECT_NEAR(p.centre().x, 0.0, 0.1);
    EXPECT_NEAR(p.centre().y, 0.0, 0.15);
    const double fill = std::max(p.hi.x - p.lo.x, p.hi.y - p.lo.y) / 2.0;  // 1: the frame's width or height
    EXPECT_GT(fill, 0.45);
    EXPECT_LE(p.hi.x, 1.0);
    EXPECT_GE(p.lo.x, -1.0);
    EXPECT_LE(p.hi.y, 1.0);
    EXPECT_GE(p.lo.y, -1.0);
  }
}

TEST(GltfAutoCamera, FramesTheBoundObjectNotTheBackdrop) {
  const SceneDescription s = loadGltf(sourceDir() / "scenes/preview.gltf");
  std::vector<Mesh> bound;
  for (const Mesh& m : s.meshes)
    if (m.material >= 0 && !s.materials[size_t(m.material)].glossyMaterial.empty()) bound.push_back(m);
  ASSERT_FALSE(bound.empty());
  ASSERT_LT(bound.size(), s.meshes.size());
  const Projection p = project(autoCamera(s), bound, 1.0);
  EXPECT_NEAR(p.centre().x, 0.0, 0.1);
  EXPECT_NEAR(p.centre().y, 0.0, 0.15);
  EXPECT_GT(std::max(p.hi.x - p.lo.x, p.hi.y - p.lo.y) / 2.0, 0.45);
}

TEST(GltfAutoCamera, SceneWithoutCameraRendersTheObjectCentred) {
  TempDir dir;
  const auto path = lonelyBox().writeGlb(dir, "box");
  const RunResult r = runGlossy({"render", "--scene", path.string(), "--width", "32", "--height", "32", "--spp", "4",
                                 "--env-constant", "1", "-o", (dir / "box.exr").string()});
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("no camera"), std::string::npos) << r.err;
  const RgbImage image = readRgbImage(dir / "box.exr");
  // Under a constant sky of 1 the grey box is darker than the background it hides.
  double sumX = 0, sumY = 0;
  int object = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float v = image.pixels[3 * size_t(y * image.width + x)];
      ASSERT_TRUE(std::isfinite(v));
      if (v < 0.98f) {
        ++object;
        sumX += x + 0.5;
        sumY += y + 0.5;
      }
    }
  const double fraction = double(object) / (image.width * image.height);
  EXPECT_GT(fraction, 0.15);
  EXPECT_LT(fraction, 0.9);
  ASSERT_GT(object, 0);
  EXPECT_NEAR(sumX / object, 16.0, 3.0);
  EXPECT_NEAR(sumY / object, 16.0, 3.0);

  // --camera auto is the same camera; a name the scene lacks still fails.
  const RunResult a = runGlossy({"render", "--scene", path.string(), "--camera", "auto", "--width", "32", "--height", "32",
                                 "--spp", "4", "--env-constant", "1", "-o", (dir / "auto.exr").string()});
  ASSERT_EQ(a.status, 0) << a.err;
  EXPECT_EQ(readRgbImage(dir / "auto.exr").pixels, image.pixels);
  expectOneLineError(runGlossy({"render", "--scene", path.string(), "--camera", "Main", "-o", (dir / "x.exr").string()}),
                     "no camera named 'Main'");
}

TEST(GltfAutoCamera, CameraAutoOverridesTheScenesCamera) {
  TempDir dir;
  const auto sphere = (sourceDir() / "scenes/sphere.gltf").string();
  const auto run = [&](std::vector<std::string> extra, const std::string& out) {
    std::vector<std::string> args = {"render", "--scene", sphere, "--width", "16", "--height", "16", "--spp", "1",
                                     "--env-constant", "1", "-o", (dir / out).string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = runGlossy(args);
    EXPECT_EQ(r.status, 0) << r.err;
    return readRgbImage(dir / out).pixels;
  };
  EXPECT_NE(run({"--camera", "auto"}, "auto.exr"), run({}, "own.exr"));
}

}  // namespace glossy::test
