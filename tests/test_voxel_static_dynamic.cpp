// Static plus dynamic: the per-vertex bake against a closed form, the dynamic region plan, and
// baked static AO combined with the dynamic grid's AO against the reference of the whole scene.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <tuple>

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
#include "voxel/VertexAOFit.h"

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

TEST(StaticDynamic, RegionHoldsTheDynamicCastersAndStaticPartsWithinR) {
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
  EXPECT_NEAR(r.min.z, 0.0, 1e-9);  // the floor's part (nothing static below it)
  EXPECT_NEAR(r.max.z, 2.2, 1e-9);  // the sphere's top (nothing static above it)
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
  const HybridMarchConstants c = makeHybridMarchConstants(hs, frameContext(hs.common, 1.5, Falloff::Binary), plan.region.frame);

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

// Least-squares vertex values: a linear function over the mesh is recovered exactly (the
// interpolation can represent it), a vertex without samples gets its neighbours' mean, bad input
// is refused.
TEST(VertexAOFit, RecoversLinearFunctionsAndFillsVerticesWithoutSamples) {
  const auto plane = makeGridPlane(2.0, 2.0, 8, 8);
  auto f = [](const glm::vec3& p) { return 0.3f + 0.2f * p.x - 0.1f * p.y; };
  std::vector<VertexFitSample> samples;
  for (const auto& t : plane->triangles)
    for (const glm::vec3 w : {glm::vec3(0.6f, 0.2f, 0.2f), glm::vec3(0.2f, 0.6f, 0.2f), glm::vec3(0.2f, 0.2f, 0.6f)}) {
      const glm::vec3 p = w.x * plane->positions[t.x] + w.y * plane->positions[t.y] + w.z * plane->positions[t.z];
      samples.push_back({t, w, f(p), 1.0f});
    }
  const VertexFitResult r = fitVertexValues(plane->positions.size(), plane->triangles, samples, 1e-6);
  double worst = 0.0;
  for (std::size_t i = 0; i < plane->positions.size(); ++i)
    worst = std::max(worst, double(std::abs(r.values[i] - f(plane->positions[i]))));
  EXPECT_LT(worst, 1e-4) << r.iterations << " iterations, residual " << r.residual;

  // Four vertices in a row, samples only on the first and last triangle's far corners.
  const std::vector<glm::uvec3> strip = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}};
  const std::vector<VertexFitSample> ends = {{{0, 1, 4}, {1, 0, 0}, 1.0f, 1.0f}, {{2, 3, 4}, {0, 1, 0}, 0.0f, 1.0f},
                                             {{0, 1, 4}, {0, 0, 1}, 0.5f, 1.0f}};
  const VertexFitResult gap = fitVertexValues(5, strip, ends);
  EXPECT_NEAR(gap.values[0], 1.0f, 0.01f);
  EXPECT_NEAR(gap.values[3], 0.0f, 0.01f);
  EXPECT_GT(gap.values[1], gap.values[2]);  // in between, following the neighbours
  EXPECT_THROW(fitVertexValues(3, strip, ends), std::invalid_argument);
  EXPECT_THROW(fitVertexValues(5, strip, ends, 0.0), std::invalid_argument);
  std::vector<VertexFitSample> nan = ends;
  nan[0].value = NAN;
  EXPECT_THROW(fitVertexValues(5, strip, nan), std::invalid_argument);
}

namespace {
// A floor of 0.25 cells and two walls, R = 1: the cases per-vertex bakes get wrong. The back wall's
// faces fall between the floor's vertices (the vertex row y = 1.5 lies under it); the front wall
// stands on vertex rows (y = -1.25 and -1.0: the row at its face is on the contact line).
struct WallScene {
  Scene scene;
  std::shared_ptr<TriangleMesh> floor = makeGridPlane(6.0, 6.0, 24, 24);
  WallScene() {
    addPlaced(*scene.root, floor, glm::dmat4(1.0), glm::vec3(1.0f), "floor");
    addPlaced(*scene.root, makeBox({4.0, 0.3, 2.0}), translation({0.0, 1.5, 1.0}), glm::vec3(1.0f), "wall");
    addPlaced(*scene.root, makeBox({4.0, 0.25, 2.0}), translation({0.0, -1.125, 1.0}), glm::vec3(1.0f), "front wall");
    scene.root->setAORadius(1.0);
  }
};
}  // namespace

TEST(VertexAOBake, InsideOccluderTellsBuriedPointsFromOpenOnes) {
  WallScene w;
  EmbreeScene embree(*w.scene.root);
  EXPECT_TRUE(insideOccluder(embree, {0.0f, 1.5f, 0.0f}, {0, 0, 1}, 16, 1));    // under the wall
  EXPECT_TRUE(insideOccluder(embree, {1.9f, 1.4f, 0.0f}, {0, 0, 1}, 16, 2));    // just inside its end
  EXPECT_FALSE(insideOccluder(embree, {0.0f, 1.3f, 0.0f}, {0, 0, 1}, 16, 3));   // at its foot, outside
  EXPECT_FALSE(insideOccluder(embree, {0.0f, 1.35f, 1.0f}, {0, -1, 0}, 16, 4)); // on its face
  EXPECT_FALSE(insideOccluder(embree, {2.5f, -2.0f, 0.0f}, {0, 0, 1}, 16, 5));  // open floor
}

// The visible floor next to each wall: AO interpolated from the vertices against the reference at
// the same points. At the vertices, the row under the back wall reads as buried and the row on
// the front wall's contact line as half walled in; the surface fit follows the floor itself.
TEST(VertexAOBake, SurfaceFitFollowsTheFloorAtTheFootOfAWall) {
  WallScene w;
  EmbreeScene embree(*w.scene.root);
  VertexBakeOptions o;
  o.samples = 256;
  o.radius = 1.0;
  const std::vector<float> atVertices = bakeVertexAO(embree, *w.floor, glm::dmat4(1.0), o);
  o.mode = VertexBakeMode::SurfaceFit;
  o.samples = 128;
  const std::vector<float> fitted = bakeVertexAO(embree, *w.floor, glm::dmat4(1.0), o);
  ASSERT_EQ(fitted.size(), w.floor->positions.size());
  // Points on the visible floor up to 0.35 (R / 4 and a bit) from each wall's face, |x| < 1.8:
  // the cells next to the walls.
  for (const auto& [name, face, away] : {std::tuple<const char*, float, float>{"back wall, vertices under it", 1.345f, -1.0f},
                                         {"front wall, vertices on its foot", -0.995f, 1.0f}}) {
    SurfaceSamples pts;
    pts.resize(48, 10);
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 48; ++i) {
        const std::size_t k = pts.index(i, j);
        pts.position[k] = glm::vec3(-1.8f + 3.6f * (i + 0.37f) / 48.0f, face + away * 0.35f * (j + 0.5f) / 10.0f, 0.0f);
        pts.normal[k] = glm::vec3(0, 0, 1);
        pts.covered[k] = 1;
      }
    const AOBuffer ref = computeReferenceAO(embree, pts, sceneReferenceOptions(*w.scene.root, 2048, 7));
    double fitSq = 0.0, vertexSq = 0.0;
    for (std::size_t k = 0; k < pts.pixelCount(); ++k) {
      const float r = ref.ao[k];
      fitSq += std::pow(floorBakeAt(*w.floor, fitted, pts.position[k].x, pts.position[k].y) - r, 2);
      vertexSq += std::pow(floorBakeAt(*w.floor, atVertices, pts.position[k].x, pts.position[k].y) - r, 2);
    }
    const double fitRmse = std::sqrt(fitSq / pts.pixelCount()), vertexRmse = std::sqrt(vertexSq / pts.pixelCount());
    std::cout << std::fixed << std::setprecision(4) << "floor next to the " << name << " (cells of R/4): surface fit rmse "
              << fitRmse << ", at vertices " << vertexRmse << "\n";
    EXPECT_LT(fitRmse, 0.015) << name;
    EXPECT_LT(fitRmse, 0.35 * vertexRmse) << name;
  }
  VertexBakeOptions bad = o;
  bad.samples = 0;
  EXPECT_THROW(bakeVertexAO(embree, *w.floor, glm::dmat4(1.0), bad), std::invalid_argument);
}

// Box mode: the settings' box is the region, split into the dynamic and static casters in it.
TEST(StaticDynamic, BoxModeSplitsTheBoxsCasters) {
  Scene3 s(true);
  const auto instances = collectInstances(*s.scene.root, kCastsAO);
  std::vector<Bounds> bounds;
  for (const auto& inst : instances) bounds.push_back(inst.geometry->mesh()->bounds().transformed(inst.world));
  const ViewFrustum f = ViewFrustum::covering(s.scene.camera, 4.0 / 3.0, worldBounds(*s.scene.root));
  HybridSettings hs;
  hs.regionBox = Bounds{{-1.5, -1.5, -0.5}, {1.5, 1.5, 2.5}};  // the sphere and the floor, not the box
  const StaticDynamicPlan plan = planStaticDynamic(bounds, {true, true, false}, f, 1.5, hs);
  ASSERT_FALSE(plan.empty);
  EXPECT_EQ(plan.dynamicCasters, std::vector<std::size_t>{2});
  EXPECT_EQ(plan.staticCasters, std::vector<std::size_t>{0});
  EXPECT_EQ(plan.allCasters, (std::vector<std::size_t>{0, 2}));
  EXPECT_EQ(dynamicBoundsOnly(bounds, {true, true, false})[0].valid(), false);
}
