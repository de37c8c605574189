// The reference's hemisphere follows the geometry, not the shading normal. Across a sharp edge whose
// vertices are shared, the interpolated normal leans up to 45 degrees off the face, and a hemisphere
// around it reaches into the wall (a bright blotch of false occlusion on a box's back wall). The
// oracle shares nothing with the G-buffer: CPU primary rays through each pixel centre and the hit
// triangle's geometric normal; both references must agree on every pixel where the two see the same
// surface point. The shading-normal hemisphere is measured beside it, to show the case bites.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "core/Geometry.h"
#include "core/Transform.h"
#include <glm/gtc/matrix_transform.hpp>
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "reference/Metrics.h"
#include "reference/PrimarySamples.h"
#include "headless/FrameCapture.h"
#include "headless/SceneView.h"
#include "scenes/BuiltinScenes.h"
#include "scenes/Shapes.h"

using namespace aokit;

namespace {

// A unit cube on the floor as a plain OBJ has it: eight shared corners, smooth normals, and no
// front face (-y), so the eye sees the inside of its back wall and its bottom.
std::shared_ptr<TriangleMesh> sharedVertexBoxWithoutFront() {
  auto m = std::make_shared<TriangleMesh>();
  for (int k = 0; k < 8; ++k) m->positions.emplace_back(k & 1 ? 0.5f : -0.5f, k & 2 ? 0.5f : -0.5f, k & 4 ? 1.0f : 0.0f);
  const unsigned quads[5][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};  // outward
  for (const auto& q : quads) {
    m->triangles.emplace_back(q[0], q[1], q[2]);
    m->triangles.emplace_back(q[0], q[2], q[3]);
  }
  m->computeNormals();
  return m;
}

Scene sharedVertexBoxScene() {
  Scene scene;
  scene.root->addChild(std::make_shared<Geometry>(makeGridPlane(8.0, 8.0, 64, 64), glm::vec3(1.0f)));
  scene.root->addChild(std::make_shared<Geometry>(sharedVertexBoxWithoutFront(), glm::vec3(1.0f)));
  scene.root->setAORadius(1.5);
  scene.camera.position = {0.4, -6.5, 3.0};
  scene.camera.focalPoint = {0.0, 0.0, 0.5};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 20.0;
  return scene;
}

struct Comparison {
  double rmseGeometric = 0.0, rmseShading = 0.0;              // every pixel both see
  double insideGeometric = 0.0, insideShading = 0.0;          // the box's inside faces alone
  double meanShading = 0.0;                                   // shading minus oracle, inside
  std::size_t inside = 0;  // compared pixels on the box's inside faces
};

// References on the rasterized G-buffer (both hemispheres) against the one on primary hits with
// geometric normals, on the pixels where the two see the same point.
Comparison compare(Scene scene, int w, int h, int samples) {
  SceneView view(scene, w, h);
  const SurfaceSamples g = captureSurfaces(view.window, view.renderer);
  EmbreeScene embree(*scene.root);
  const SurfaceSamples p = castPrimarySamples(embree, scene.camera, w, h, PrimaryNormal::Geometric);
  ReferenceOptions opt = sceneReferenceOptions(*scene.root, samples, 7);
  AOBuffer geometric = computeReferenceAO(embree, g, opt);
  opt.hemisphere = Hemisphere::Shading;
  AOBuffer shading = computeReferenceAO(embree, g, opt);
  opt.hemisphere = Hemisphere::Geometric;
  // The same seed: where the two agree on point and facet, they cast the same rays (common random
  // numbers), so what differs is the input, not the noise.
  AOBuffer oracle = computeReferenceAO(embree, p, opt);
  Comparison c;
  std::vector<std::uint8_t> inside(g.pixelCount(), 0);
  for (std::size_t i = 0; i < g.pixelCount(); ++i) {
    const bool same = g.covered[i] && p.covered[i] &&
                      glm::distance(g.position[i], p.position[i]) <
                          1e-3 * glm::distance(glm::dvec3(p.position[i]), scene.camera.position);
    geometric.covered[i] = shading.covered[i] = oracle.covered[i] = same;
    const glm::vec3 q = p.position[i];
    inside[i] = same && std::abs(q.x) < 0.5f && std::abs(q.y) < 0.5f && q.z < 1.0f;
    c.inside += inside[i];
  }
  c.rmseGeometric = compareAO(geometric, oracle).rmse;
  c.rmseShading = compareAO(shading, oracle).rmse;
  geometric.covered = shading.covered = oracle.covered = inside;
  c.insideGeometric = compareAO(geometric, oracle).rmse;
  c.insideShading = compareAO(shading, oracle).rmse;
  double sum = 0.0;
  for (std::size_t i = 0; i < inside.size(); ++i)
    if (inside[i]) sum += shading.ao[i] - oracle.ao[i];
  c.meanShading = c.inside ? sum / c.inside : 0.0;
  return c;
}

// AOKIT_ORACLE_FULL=1: the size (1024 x 768, 512 rays per pixel).
struct Size {
  int w, h, samples;
};
Size testSize() {
  if (std::getenv("AOKIT_ORACLE_FULL")) return {1024, 768, 512};
  return {256, 192, 128};
}

void report(const char* what, const Size& s, const Comparison& c) {
  std::printf("%s %dx%d, %d rays, against primary hits with geometric normals: RMSE %.4f (geometric "
              "hemisphere), %.4f (shading); inside the box (%zu pixels) %.4f and %.4f, shading's mean error %+.4f\n",
              what, s.w, s.h, s.samples, c.rmseGeometric, c.rmseShading, c.inside, c.insideGeometric,
              c.insideShading, c.meanShading);
}

}  // namespace

TEST(ReferenceHemisphere, SharedVertexBoxFollowsItsFaces) {
  const Size s = testSize();
  const Comparison c = compare(sharedVertexBoxScene(), s.w, s.h, s.samples);
  report("shared-vertex box", s, c);
  ASSERT_GT(c.inside, 500u) << "the camera must see into the box";
  EXPECT_LT(c.rmseGeometric, 0.01);
  EXPECT_LT(c.insideGeometric, 0.01);
  EXPECT_GT(c.insideShading, 0.05) << "the case no longer bites: the shading hemisphere should be far off here";
}

TEST(ReferenceHemisphere, OpenBoxFollowsItsFaces) {
  const Size s = testSize();
  const Comparison c = compare(makeBuiltinScene("open-box"), s.w, s.h, s.samples);
  report("open box", s, c);
  ASSERT_GT(c.inside, 50u) << "the camera must see into the box";
  EXPECT_LT(c.rmseGeometric, 0.01);
  EXPECT_LT(c.insideGeometric, 0.01);
}

namespace {
// Of the pixels off the floor where the G-buffer and a primary ray see the same point, the
// fraction whose G-buffer normal is within 0.5 degrees of the hit triangle's own.
double facetAgreement(Scene scene, int w, int h, bool facetNormals) {
  SceneView view(scene, w, h);
  const SurfaceSamples g = captureSurfaces(view.window, view.renderer, facetNormals);
  EmbreeScene embree(*scene.root);
  const SurfaceSamples p = castPrimarySamples(embree, scene.camera, w, h, PrimaryNormal::Geometric);
  std::size_t same = 0, agree = 0;
  for (std::size_t i = 0; i < g.pixelCount(); ++i) {
    if (!g.covered[i] || !p.covered[i]) continue;
    if (glm::distance(g.position[i], p.position[i]) > 1e-3 * glm::distance(glm::dvec3(p.position[i]), scene.camera.position))
      continue;
    if (p.position[i].z < 1e-4f) continue;  // the floor: flat, both normals agree anyway
    ++same;
    agree += glm::dot(glm::normalize(g.normal[i]), p.normal[i]) > std::cos(glm::radians(0.5f));
  }
  EXPECT_GT(same, 5000u);
  return same ? static_cast<double>(agree) / same : 0.0;
}
}  // namespace

// The methods' `normal=facet`: the G-buffer then carries each triangle's own normal, turned to
// the eye, as the reference's hemisphere has it (checked against primary rays, not the G-buffer).
TEST(ReferenceHemisphere, FacetNormalsInTheGBufferAreTheTrianglesOwn) {
  Scene sphere;
  sphere.root->addChild(std::make_shared<Geometry>(makeGridPlane(8.0, 8.0, 8, 8), glm::vec3(1.0f)));
  auto coarse = std::make_shared<Transform>();
  coarse->setMatrix(glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 1.2)));
  coarse->addChild(std::make_shared<Geometry>(makeUVSphere(1.0, 12, 6), glm::vec3(1.0f)));
  sphere.root->addChild(coarse);
  sphere.camera.position = {0.0, -6.5, 4.0};
  sphere.camera.focalPoint = {0.0, 0.0, 0.7};
  for (auto [what, scene] : {std::pair<const char*, Scene>{"shared-vertex box", sharedVertexBoxScene()},
                             std::pair<const char*, Scene>{"coarse sphere", sphere}}) {
    const double facet = facetAgreement(scene, 256, 192, true), shading = facetAgreement(scene, 256, 192, false);
    std::printf("%s: G-buffer normals within 0.5 degrees of the hit triangle's: %.4f (normal=facet), %.4f (shading)\n",
                what, facet, shading);
    EXPECT_GT(facet, 0.995) << what;
    EXPECT_LT(shading, 0.9) << what << ": the shading normals should lean off the facets here";
  }
}
