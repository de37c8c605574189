// What the field pass computes on the CPU before drawing: the buffer layout, the influence spheres
// that culling relies on (the field is exactly 0 beyond them), the screen rectangles (every texel a
// sphere can reach lies inside), the plan of fields per distinct mesh and scale, and settings.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "core/Geometry.h"
#include "core/NodeVisitor.h"
#include "fields/FieldBaker.h"
#include "fields/FieldGpuData.h"
#include "fields/FieldInstances.h"
#include "fields/FieldScreenRect.h"
#include "fields/FieldTechnique.h"
#include "methods/MethodRegistry.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

using namespace aokit;

namespace {

std::shared_ptr<const BakedField> bake(const TriangleMesh& mesh, FieldKind kind, int resolution, double radius) {
  FieldBakeSettings s;
  s.kind = kind;
  s.resolution = resolution;
  s.selfOcclusion = false;
  s.threads = 2;
  s.raysPerSample = 32;
  s.gridRays = 64;
  return std::make_shared<BakedField>(bakeField(mesh, s, radius, Falloff::Binary));
}

glm::dvec3 randomUnit(std::mt19937& rng) {
  std::normal_distribution<double> g;
  return glm::normalize(glm::dvec3(g(rng), g(rng), g(rng)));
}

}  // namespace

TEST(FieldGpuData, LayoutOffsetsAndExactBytes) {
  const auto box = makeBox({1.0, 2.0, 0.5});
  const auto cube = bake(*box, FieldKind::Cube, 6, 1.0);
  const auto cube2 = bake(*box, FieldKind::Cube, 9, 1.0);
  const auto grid = bake(*box, FieldKind::Grid6, 8, 1.0);
  const FieldGpuData d = packFields({cube, grid, cube2});
  EXPECT_TRUE(d.hasCube);
  EXPECT_TRUE(d.hasGrid);
  EXPECT_EQ(d.gridKind, FieldKind::Grid6);
  // (N + 2)^2 x 6 x 7 x 4 per cube field, N^3 x 6 x 4 per grid6.
  EXPECT_EQ(d.fieldBytes, static_cast<std::size_t>(8 * 8 * 6 * 7 * 4 + 11 * 11 * 6 * 7 * 4 + 8 * 8 * 8 * 6 * 4));
  EXPECT_EQ(d.texels4.size(), (8u * 8 * 6 + 11u * 11 * 6) * 4);
  EXPECT_EQ(d.texels3.size(), (8u * 8 * 6 + 8u * 8 * 8 * 2 + 11u * 11 * 6) * 3);
  // Field ints: kind, N, base in texels4, base in texels3.
  EXPECT_EQ(d.fieldInts[0], 0u);
  EXPECT_EQ(d.fieldInts[1], 6u);
  EXPECT_EQ(d.fieldInts[4], 1u);
  EXPECT_EQ(d.fieldInts[5], 8u);
  EXPECT_EQ(d.fieldInts[7], 8u * 8 * 6);        // the grid's terms follow the first cube's C0
  EXPECT_EQ(d.fieldInts[10], 8u * 8 * 6);       // the second cube's (a, b, c, r0) follow the first's
  EXPECT_EQ(d.fieldInts[11], 8u * 8 * 6 + 1024u);
  // A texel lands where its base says.
  EXPECT_EQ(d.texels4[d.fieldInts[10] * 4 + 5], cube2->radial.occlusion[5]);
  EXPECT_EQ(d.texels3[d.fieldInts[7] * 3 + 7], grid->grid.texels[7]);
  EXPECT_FLOAT_EQ(d.fieldFloats[0], static_cast<float>(cube->radial.rMax));
  EXPECT_FLOAT_EQ(d.fieldFloats[kFieldFloatsPerField + 4], static_cast<float>(grid->grid.size.x));

  const auto grid4 = bake(*box, FieldKind::Grid4, 8, 1.0);
  EXPECT_THROW(packFields({grid, grid4}), std::invalid_argument);
  EXPECT_THROW(packFields({cube, nullptr}), std::invalid_argument);
  const FieldGpuData empty = packFields({});
  EXPECT_EQ(empty.fieldCount, 0);
  EXPECT_FALSE(empty.texels4.empty());  // a buffer texture cannot be empty
}

TEST(FieldGpuData, OccludersCubeFieldsFirstInGivenOrder) {
  const auto box = makeBox(glm::dvec3(1.0));
  const std::vector<std::shared_ptr<const BakedField>> fields{bake(*box, FieldKind::Grid6, 8, 1.0),
                                                              bake(*box, FieldKind::Cube, 6, 1.0)};
  std::vector<FieldOccluder> occ;
  for (int i = 0; i < 70; ++i) occ.push_back({i % 3 == 0 ? 1 : 0, glm::translate(glm::dmat4(1.0), glm::dvec3(i, 0, 0)), 10u + i});
  const OccluderGpuData d = packOccluders(fields, occ, 1.0);
  EXPECT_EQ(d.occluderCount, 70);
  EXPECT_EQ(d.cubeCount, 24);  // i = 0, 3, ..., 69
  EXPECT_EQ(d.cubeWords, 1);
  EXPECT_EQ(d.words, 3);
  for (int k = 0; k < 70; ++k) {
    EXPECT_EQ(fields[occ[d.order[k]].field]->info.kind == FieldKind::Cube, k < 24);
    EXPECT_EQ(d.ints[k * 4], occ[d.order[k]].instanceId);
    if (k > 0 && k != 24) EXPECT_LT(d.order[k - 1], d.order[k]) << "the given order within each kind";
  }
  // M = world -> field coordinates: the occluder's own origin maps to minus the field centre (cube).
  const int first = d.order[0];
  const glm::dvec3 origin = glm::dvec3(occ[first].occluderToWorld[3]);
  const float* m = &d.floats[0];
  const glm::dvec3 x(m[0] * origin.x + m[1] * origin.y + m[2] * origin.z + m[3],
                     m[4] * origin.x + m[5] * origin.y + m[6] * origin.z + m[7],
                     m[8] * origin.x + m[9] * origin.y + m[10] * origin.z + m[11]);
  EXPECT_NEAR(glm::distance(x, -fields[1]->radial.centre), 0.0, 1e-5);
  occ.push_back({5, glm::dmat4(1.0), 1u});
  EXPECT_THROW(packOccluders(fields, occ, 1.0), std::invalid_argument);
}

TEST(FieldGpuData, NothingBeyondTheInfluenceSphere) {
  // Culling drops an occluder wherever a receiver lies outside its sphere: the CPU evaluator must
  // give exactly 0 there, for any normal, for rotated and scaled placements.
  const auto box = makeBox({1.0, 0.6, 1.4});
  const FieldEvalSettings s;
  std::mt19937 rng(3);
  for (FieldKind kind : {FieldKind::Cube, FieldKind::Grid6, FieldKind::Grid4}) {
    const auto field = bake(*box, kind, 8, 0.8);
    for (int t = 0; t < 3; ++t) {
      const glm::dmat4 o = glm::translate(glm::dmat4(1.0), glm::dvec3(t, -2.0 * t, 0.5)) *
                           glm::rotate(glm::dmat4(1.0), 0.7 * t, glm::dvec3(0.3, 1.0, 0.2)) *
                           glm::scale(glm::dmat4(1.0), glm::dvec3(1.0 + 0.5 * t));
      const InfluenceSphere sphere = influenceSphere(*field, o, s.bias);
      int inside = 0;
      for (int i = 0; i < 3000; ++i) {
        const double r = sphere.radius * (0.2 + 1.3 * std::uniform_real_distribution<double>(0, 1)(rng));
        const glm::dvec3 p = sphere.centre + r * randomUnit(rng);
        const double a = evaluateOccluder(*field, o, p, randomUnit(rng), s).occlusion;
        if (r > sphere.radius * (1.0 + 1e-9)) {
          ASSERT_EQ(a, 0.0) << fieldKindName(kind) << " at " << r / sphere.radius << " radii";
        } else {
          inside += a > 0.0;
        }
      }
      EXPECT_GT(inside, 100) << "the sphere is not larger than it needs to be to hold something";
    }
  }
}

TEST(FieldScreenRect, HoldsEveryTexelTheSphereReaches) {
  // A perspective camera like VTK's (30 degrees, 4:3), target at half the screen resolution: every
  // point of a sphere projects into the rectangle; spheres behind the eye give nothing, spheres
  // around the eye everything.
  TargetGeometry t;
  const double f = 1.0 / std::tan(glm::radians(15.0)), aspect = 4.0 / 3.0, n = 0.1, fa = 100.0;
  const float clip[3][4] = {{static_cast<float>(f / aspect), 0, 0, 0}, {0, static_cast<float>(f), 0, 0}, {0, 0, -1, 0}};
  std::copy(&clip[0][0], &clip[0][0] + 12, &t.clip[0][0]);
  (void)n;
  (void)fa;
  t.gbufferWidth = t.screenWidth = 401;
  t.gbufferHeight = t.screenHeight = 300;
  t.downsample = 2;
  t.targetWidth = 201;
  t.targetHeight = 150;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  long long tight = 0, total = 0;
  for (int s = 0; s < 300; ++s) {
    const glm::dvec3 c(6 * u(rng), 5 * u(rng), -2.0 - 10.0 * (u(rng) + 1.0));
    const double r = 0.2 + 1.5 * (u(rng) + 1.0);
    const TexelRect rect = sphereTexelRect(c, r, t);
    int seen = 0;
    for (int i = 0; i < 400; ++i) {
      const glm::dvec3 p = c + r * std::cbrt(0.5 * (u(rng) + 1.0)) * randomUnit(rng);
      if (p.z >= -1e-3) continue;
      const double x = clip[0][0] * p.x / -p.z, y = clip[1][1] * p.y / -p.z;
      if (std::abs(x) > 1.0 || std::abs(y) > 1.0) continue;
      // The pixel whose centre is nearest, and the target texel standing for it (or its block).
      const int px = static_cast<int>(std::floor((x + 1.0) * 0.5 * t.screenWidth));
      const int py = static_cast<int>(std::floor((y + 1.0) * 0.5 * t.screenHeight));
      const int cx = px / t.downsample, cy = py / t.downsample;
      ASSERT_FALSE(rect.empty()) << "sphere " << s;
      ASSERT_TRUE(cx >= rect.x0 && cx <= rect.x1 && cy >= rect.y0 && cy <= rect.y1) << "sphere " << s;
      ++seen;
    }
    if (seen > 0 && c.z + r < -0.5) {
      // Projected disc area against the rectangle: conservative but not wasteful.
      const double rp = r / std::sqrt(c.z * c.z - r * r) * f * 0.5 * t.screenHeight / t.downsample;
      tight += static_cast<long long>(3.14159 * rp * rp);
      total += rect.area();
    }
  }
  EXPECT_LT(total, 3 * tight) << "rectangles much larger than the spheres' discs";
  EXPECT_TRUE(sphereTexelRect({0, 0, 5}, 1.0, t).empty());                 // behind the eye
  EXPECT_EQ(sphereTexelRect({0, 0, -0.5}, 1.0, t).area(), 201LL * 150);    // around the eye
  EXPECT_TRUE(sphereTexelRect({100, 0, -5}, 1.0, t).empty());              // off to the side
}

TEST(FieldInstances, OneFieldPerMeshAndScale) {
  auto root = std::make_shared<Group>();
  const auto cube = makeBox(glm::dvec3(1.0));
  const auto plane = makeGridPlane(10.0, 10.0, 4, 4);
  addPlaced(*root, cube, translation({1, 0, 0}) * rotation(30, {0, 0, 1}), glm::vec3(0.8f), "a");
  addPlaced(*root, cube, translation({3, 0, 0}) * rotation(-70, {1, 1, 0}), glm::vec3(0.8f), "b");
  addPlaced(*root, cube, scaling(glm::dvec3(2.0)), glm::vec3(0.8f), "c");             // R / 2
  addPlaced(*root, cube, scaling({1.0, 1.0, 3.0}), glm::vec3(0.8f), "d");             // its own
  addPlaced(*root, plane, glm::dmat4(1.0), glm::vec3(0.8f), "floor");
  const auto instances = collectInstances(*root, kCastsAO);
  const FieldPlan plan = planFields(instances, 1.0);
  ASSERT_EQ(plan.occluders.size(), 5u);
  ASSERT_EQ(plan.fields.size(), 4u);
  EXPECT_EQ(plan.occluders[0].field, plan.occluders[1].field);
  EXPECT_DOUBLE_EQ(plan.fields[plan.occluders[0].field].radius, 1.0);
  EXPECT_DOUBLE_EQ(plan.fields[plan.occluders[2].field].radius, 0.5);
  EXPECT_EQ(plan.fields[plan.occluders[0].field].kind, FieldKind::Cube);
  EXPECT_EQ(plan.fields[plan.occluders[4].field].kind, FieldKind::Grid6);  // flat
  // The non-uniform one: its mesh is stretched, and O = world L^-1 is a similarity.
  const PlannedField& d = plan.fields[plan.occluders[3].field];
  EXPECT_NEAR(d.mesh->bounds().max.z - d.mesh->bounds().min.z, 3.0, 1e-6);
  EXPECT_TRUE(isSimilarity(instances[3].world * plan.occluders[3].correction));
  const FieldPlan fixed = planFields(instances, 1.0, FieldKind::Grid4);
  for (const auto& f : fixed.fields) EXPECT_EQ(f.kind, FieldKind::Grid4);

  double s = 0.0;
  EXPECT_TRUE(isSimilarity(rotation(33, {1, 2, 3}) * scaling(glm::dvec3(0.25)), &s));
  EXPECT_DOUBLE_EQ(s, 0.25);
  EXPECT_FALSE(isSimilarity(scaling({1, 1, 1.001})));
  EXPECT_FALSE(isSimilarity(glm::dmat4(0.0)));
  EXPECT_TRUE(isFlat(*makeGridPlane(4.0, 1.0, 2, 2)));
  EXPECT_FALSE(isFlat(*makeBox({1.0, 1.0, 0.2})));
  EXPECT_FALSE(isFlat(*makeCylinder(0.1, 5.0, 16)));  // a rod is compact in every direction but one
  EXPECT_TRUE(isFlat(*makeBox({3.0, 2.0, 0.1})));

  addPlaced(*root, cube, scaling({0.0, 1.0, 1.0}), glm::vec3(0.8f), "flat to nothing");
  EXPECT_THROW(planFields(collectInstances(*root, kCastsAO), 1.0), std::invalid_argument);
}

TEST(FieldSettings, BadSettingsGiveOneLineErrorsInTheUsersWords) {
  auto message = [](const FieldSettings& s) -> std::string {
    try {
      validate(s);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  FieldSettings p;
  EXPECT_EQ(message(p), "");
  p.common.scale = static_cast<AOScale>(3);
  EXPECT_EQ(message(p).rfind("field: scale must be one of 1, 0.5, 0.25, got", 0), 0u) << message(p);
  p = {};
  p.common.upsample.window = -1;
  EXPECT_EQ(message(p).rfind("field: window must be", 0), 0u) << message(p);
  p = {};
  p.sliceAxis = 3;
  EXPECT_EQ(message(p).rfind("field: sliceAxis must be one of x, y, z", 0), 0u) << message(p);
  p = {};
  p.slicePosition = NAN;
  EXPECT_EQ(message(p).rfind("field: slice must be", 0), 0u) << message(p);
  p = {};
  p.bake.resolution = 1;
  EXPECT_EQ(message(p), "field: resolution must be auto (from the occluder's size against R) or an integer in 2..128, got 1");
  p = {};
  p.bake.farDistance = 1.0;
  p.bake.nearDistance = 1.5;
  EXPECT_EQ(message(p), "field: near must be below far (fractions of R)");
  // window=1 (each pixel's own texel) is one window like the others now: the same range as the
  // command line's, from the one schema.
  p = {};
  p.common.upsample.window = 1;
  EXPECT_EQ(message(p), "");
  EXPECT_NO_THROW(makeTechnique("field", "window=1"));
  FieldSettings t;
  t.kind = FieldKind::Grid6;
  t.eval.combine = FieldCombine::Cone;
  try {
    FieldTechnique bad(t);
    FAIL() << "cones on grids accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "field: combine=cone needs kind=cube or auto (grids store no cone)");
  }
}

TEST(FieldScreenRect, TileRunsHoldEveryReceiverTheSphereReaches) {
  // A floor seen from above at an angle (view depth varying over the image), tiles of 8 texels
  // with their receivers' depth ranges; spheres around and above it. Every texel whose receiver
  // lies in the sphere is in a run; the runs stay inside the sphere's rectangle and cut it down.
  TargetGeometry t;
  const double f = 1.0 / std::tan(glm::radians(15.0)), aspect = 4.0 / 3.0;
  const float clip[3][4] = {{static_cast<float>(f / aspect), 0, 0, 0}, {0, static_cast<float>(f), 0, 0}, {0, 0, -1, 0}};
  std::copy(&clip[0][0], &clip[0][0] + 12, &t.clip[0][0]);
  t.gbufferWidth = t.screenWidth = t.targetWidth = 160;
  t.gbufferHeight = t.screenHeight = t.targetHeight = 120;
  // The floor: view z of texel (x, y) from a plane z = -8 + 3 (y / 120 - 0.5) (tilted), none in
  // the top rows (background).
  auto depthOf = [&](int x, int y) { return y > 100 ? 1.0 : -8.0 + 3.0 * (y / 120.0 - 0.5) + 0.5 * (x / 160.0); };
  TileDepths tiles;
  tiles.tile = 8;
  tiles.tilesX = 20;
  tiles.tilesY = 15;
  tiles.zRange.assign(2 * 20 * 15, 0.0f);
  for (int ty = 0; ty < 15; ++ty)
    for (int tx = 0; tx < 20; ++tx) {
      float zn = -1e30f, zf = 1e30f;
      for (int y = ty * 8; y < ty * 8 + 8; ++y)
        for (int x = tx * 8; x < tx * 8 + 8; ++x) {
          const double z = depthOf(x, y);
          if (z > 0.0) continue;
          zn = std::max(zn, static_cast<float>(z));
          zf = std::min(zf, static_cast<float>(z));
        }
      tiles.zRange[2 * (ty * 20 + tx)] = zn;
      tiles.zRange[2 * (ty * 20 + tx) + 1] = zf;
    }
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1, 1);
  long long runArea = 0, rectArea = 0;
  for (int s = 0; s < 200; ++s) {
    const glm::dvec3 c(2.5 * u(rng), 2.0 * u(rng), -7.0 + 2.5 * u(rng));
    const double r = 0.3 + 0.6 * (u(rng) + 1.0);
    const TexelRect rect = sphereTexelRect(c, r, t);
    const auto runs = sphereTexelRuns(c, r, t, tiles);
    for (const auto& run : runs) {
      EXPECT_TRUE(run.x0 >= rect.x0 && run.x1 <= rect.x1 && run.y0 >= rect.y0 && run.y1 <= rect.y1);
      runArea += run.area();
    }
    rectArea += rect.area();
    for (int y = 0; y < 120; ++y)
      for (int x = 0; x < 160; ++x) {
        const double z = depthOf(x, y);
        if (z > 0.0) continue;
        const double nx = (x + 0.5) / 160 * 2 - 1, ny = (y + 0.5) / 120 * 2 - 1;
        const glm::dvec3 p(nx * -z / clip[0][0], ny * -z / clip[1][1], z);
        if (glm::distance(p, c) > r) continue;
        bool in = false;
        for (const auto& run : runs) in = in || (x >= run.x0 && x <= run.x1 && y >= run.y0 && y <= run.y1);
        ASSERT_TRUE(in) << "sphere " << s << " texel " << x << "," << y;
      }
  }
  std::printf("runs cover %.2f of the rectangles\n", double(runArea) / rectArea);
  EXPECT_LT(runArea, rectArea * 0.8);
}
