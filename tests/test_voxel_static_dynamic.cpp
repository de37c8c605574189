// Static plus dynamic: the per-vertex bake against a closed form, the dynamic region plan, and
// baked static AO combined with the dynamic grid's AO against the reference of the whole scene.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <iostream>

#include "core/Geometry.h"
#include "core/Scene.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"
#include "voxel/CpuVoxelizer.h"
#include "voxel/HybridMarch.h"
#include "voxel/StaticDynamic.h"
#include "voxel/VertexAOBake.h"

using namespace aokit;

namespace {

// Floor (static, 8 x 8 grid of 64 x 64 cells), a static box on the left, a sphere (dynamic) over
// the origin, as sphere-plane.
struct Scene3 {
  Scene scene;
  std::shared_ptr<TriangleMesh> floor = makeGridPlane(8.0, 8.0, 64, 64);
  Scene3(bool withBox) {
    addPlaced(*scene.root, floor, glm::dmat4(1.0), glm::vec3(1.0f), "floor");
    if (withBox) addPlaced(*scene.root, makeBox({0.6, 2.0, 1.5}), translation({-2.0, 0.0, 0.75}), glm::vec3(1.0f), "box");
    addPlaced(*scene.root, makeUVSphere(1.0, 128, 64), translation({0.0, 0.0, 1.2}), glm::vec3(1.0f), "sphere");
    scene.root->setAORadius(1.5);
    scene.camera.position = {0.0, -6.5, 4.0};
    scene.camera.focalPoint = {0.0, 0.0, 0.7};
  }
};

// The floor's triangle under (x, y) and the barycentrics there.
float floorBakeAt(const TriangleMesh& m, const std::vector<float>& ao, float x, float y) {
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const glm::vec3 a = m.positions[m.triangles[t].x], b = m.positions[m.triangles[t].y], c = m.positions[m.triangles[t].z];
    const float det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    const float u = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / det;
    const float v = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / det;
    if (u >= -1e-6f && v >= -1e-6f && u + v <= 1.0f + 1e-6f) return interpolateVertexAO(m, ao, t, u, v);
  }
  ADD_FAILURE() << "no floor triangle under " << x << ", " << y;
  return 0.0f;
}

}  // namespace

// A sphere of radius r centred at height h above a plane point at distance D from its centre, all
// above the horizon, occludes r^2 h / D^3 of the cosine-weighted hemisphere (radius unbounded).
TEST(VertexAOBake, FloorUnderASphereMatchesTheFormFactor) {
  Scene3 s(false);
  EmbreeScene embree(*s.scene.root);
  VertexBakeOptions o;
  o.samples = 1024;
  o.radius = 100.0;
  const std::vector<float> ao = bakeVertexAO(embree, *s.floor, glm::dmat4(1.0), o);
  ASSERT_EQ(ao.size(), s.floor->positions.size());
  double worst = 0.0, sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < ao.size(); ++i) {
    const glm::dvec3 p(s.floor->positions[i]);
    if (glm::length(glm::dvec2(p)) > 3.0) continue;
    const double D = glm::length(glm::dvec3(0, 0, 1.2) - p);
    const double exact = 1.2 / (D * D * D);
    worst = std::max(worst, std::abs(ao[i] - exact));
    sum += std::abs(ao[i] - exact);
    ++n;
  }
  EXPECT_GT(n, 1000);
  EXPECT_LT(sum / n, 0.006);
  EXPECT_LT(worst, 0.04);
  VertexBakeOptions bad = o;
  bad.samples = 0;
  EXPECT_THROW(bakeVertexAO(embree, *s.floor, glm::dmat4(1.0), bad), std::invalid_argument);
}

TEST(StaticDynamic, RegionIsTheDynamicCastersGrownByR) {
  Scene3 s(true);
  const auto instances = collectInstances(*s.scene.root, kCastsAO);
  std::vector<Bounds> bounds;
  std::vector<bool> isStatic;
  for (const auto& inst : instances) {
    bounds.push_back(inst.geometry->mesh()->bounds().transformed(inst.world));
    isStatic.push_back(inst.geometry->name() != "sphere");
  }
  const ViewFrustum f = ViewFrustum::covering(s.scene.camera, 4.0 / 3.0, worldBounds(*s.scene.root));
  const StaticDynamicPlan plan = planStaticDynamic(bounds, isStatic, f, 1.5, HybridSettings{});
  ASSERT_FALSE(plan.empty);
  EXPECT_EQ(plan.dynamicCasters, std::vector<std::size_t>{2});
  EXPECT_EQ(plan.allCasters, (std::vector<std::size_t>{0, 1, 2}));  // floor and box meet the region
  const Bounds& r = plan.region.box;
  EXPECT_NEAR(r.min.x, -2.5, 1e-9);
  EXPECT_NEAR(r.max.x, 2.5, 1e-9);
  EXPECT_NEAR(r.max.z, 3.7, 1e-9);
  EXPECT_EQ(plan.memoryBytes, 2 * plan.region.memoryBytes);
  // Everything static: nothing to voxelize.
  const StaticDynamicPlan none = planStaticDynamic(bounds, {true, true, true}, f, 1.5, HybridSettings{});
  EXPECT_TRUE(none.empty);
  EXPECT_THROW(planStaticDynamic(bounds, {true}, f, 1.5, HybridSettings{}), std::invalid_argument);
}

// Floor points between the static box and the dynamic sphere: baked (floor + box) combined with the
// dynamic grid (sphere) against the reference of everything; sphere points march the full grid.
TEST(StaticDynamic, BakedPlusDynamicMatchesTheReference) {
  Scene3 s(true);
  const auto instances = collectInstances(*s.scene.root, kCastsAO);
  std::vector<Bounds> bounds;
  std::vector<bool> isStatic;
  for (const auto& inst : instances) {
    bounds.push_back(inst.geometry->mesh()->bounds().transformed(inst.world));
    isStatic.push_back(inst.geometry->name() != "sphere");
  }
  // The static bake: static occluders only.
  Scene3 staticPart(true);
  std::vector<float> baked;
  {
    auto sphereNode = collectInstances(*staticPart.scene.root)[2].geometry;
    sphereNode->setMask(kVisible | kReceivesAO);
    EmbreeScene statics(*staticPart.scene.root);
    VertexBakeOptions o;
    o.samples = 512;
    o.radius = 1.5;
    baked = bakeVertexAO(statics, *s.floor, glm::dmat4(1.0), o);
  }
  const ViewFrustum f = ViewFrustum::covering(s.scene.camera, 4.0 / 3.0, worldBounds(*s.scene.root));
  HybridSettings hs;
  hs.rays = 128;
  hs.steps = 16;
  const StaticDynamicPlan plan = planStaticDynamic(bounds, isStatic, f, 1.5, hs);
  ASSERT_FALSE(plan.empty);
  std::vector<GeometryInstance> dyn, all;
  for (std::size_t i : plan.dynamicCasters) dyn.push_back(instances[i]);
  for (std::size_t i : plan.allCasters) all.push_back(instances[i]);
  const VoxelGrid dynamicGrid = voxelizeInstances(dyn, plan.region.frame, VoxelizeMethod::ThreeAxis, true);
  const VoxelGrid fullGrid = voxelizeInstances(all, plan.region.frame, VoxelizeMethod::ThreeAxis, true);
  const HybridMarchConstants c = makeHybridMarchConstants(hs, 1.5, Falloff::Binary, plan.region.frame);

  SurfaceSamples pts;
  pts.resize(40, 1);
  for (int i = 0; i < 30; ++i) {  // floor, x from -1.5 (by the box) to 2.0
    pts.position[i] = glm::vec3(-1.5f + 3.5f * i / 29.0f, 0.31f, 0.0f);
    pts.normal[i] = glm::vec3(0, 0, 1);
    pts.covered[i] = 1;
  }
  for (int i = 30; i < 40; ++i) {  // sphere underside, facing the box side
    const double polar = glm::radians(100.0 + 6.0 * (i - 30)), a = glm::radians(180.0 + 7.0 * (i - 30));
    const glm::dvec3 n(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar));
    pts.position[i] = glm::vec3(glm::dvec3(0, 0, 1.2) + n);
    pts.normal[i] = glm::vec3(n);
    pts.covered[i] = 1;
  }
  EmbreeScene everything(*s.scene.root);
  const AOBuffer ref = computeReferenceAO(everything, pts, sceneReferenceOptions(*s.scene.root, 4096, 3));
  double combinedSq = 0.0, bakeOnlySq = 0.0, dynamicSq = 0.0, boxShare = 0.0, sumSq = 0.0, bias = 0.0;
  for (int i = 0; i < 30; ++i) {
    const float b = floorBakeAt(*s.floor, baked, pts.position[i].x, pts.position[i].y);
    const float d = marchHybridAO(dynamicGrid, c, pts.position[i], pts.normal[i]);
    const float combined = combineBakedAndDynamic(b, d);
    combinedSq += std::pow(combined - ref.ao[i], 2) / 30;
    sumSq += std::pow(std::min(1.0f, b + d) - ref.ao[i], 2) / 30;
    bias += (combined - ref.ao[i]) / 30;
    bakeOnlySq += std::pow(b - ref.ao[i], 2) / 30;
    boxShare += b / 30;
  }
  for (int i = 30; i < 40; ++i)
    dynamicSq += std::pow(marchHybridAO(fullGrid, c, pts.position[i], pts.normal[i]) - ref.ao[i], 2) / 10;
  std::cout << std::fixed << std::setprecision(4) << "floor points: baked + dynamic rmse " << std::sqrt(combinedSq)
            << " (bias " << bias << "; additive min(1, a + b): " << std::sqrt(sumSq) << "), bake alone " << std::sqrt(bakeOnlySq) << " (mean baked AO " << boxShare
            << "); sphere points on the full grid: rmse " << std::sqrt(dynamicSq) << "\n";
  EXPECT_GT(boxShare, 0.02);  // the static box does contribute to the floor
  EXPECT_LT(std::sqrt(combinedSq), 0.06);
  EXPECT_LT(std::sqrt(combinedSq), 0.3 * std::sqrt(bakeOnlySq));
  EXPECT_LT(std::sqrt(dynamicSq), 0.06);
}
