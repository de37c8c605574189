// The CPU Hybrid AO estimator (HybridMarch.h) converges to the reference's quantity, the Embree
// estimate of 1/pi integral V k(d) cos over the hemisphere, as rays, steps and grid resolution
// grow. Prints the convergence tables the report quotes, and the normal-offset trade-off.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <tuple>
#include <sstream>

#include "core/Geometry.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "core/Transform.h"
#include "scenes/BuiltinScenes.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"
#include "voxel/CpuVoxelizer.h"
#include "voxel/HybridMarch.h"

using namespace aokit;

namespace {

const double kPi = 3.14159265358979323846;

// Points on the floor around the sphere's foot (0.1 to 2.6 from the axis) and on the sphere's
// lower half, with their exact normals: the contact region where the AO varies most.
SurfaceSamples spherePlanePoints() {
  std::vector<std::pair<glm::vec3, glm::vec3>> pts;
  for (int i = 0; i < 26; ++i) {
    const double r = 0.1 + 0.1 * i, a = 2.399963 * i;  // golden angle: spread around the sphere
    pts.push_back({glm::vec3(r * std::cos(a), r * std::sin(a), 0.0), glm::vec3(0, 0, 1)});
  }
  for (int i = 0; i < 16; ++i) {
    const double polar = glm::radians(95.0 + 75.0 * i / 15.0), a = 2.399963 * i + 0.5;
    const glm::dvec3 n(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar));
    pts.push_back({glm::vec3(glm::dvec3(0, 0, 1.2) + n), glm::vec3(n)});
  }
  SurfaceSamples s;
  s.resize(static_cast<int>(pts.size()), 1);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    s.position[i] = pts[i].first;
    s.normal[i] = pts[i].second;
    s.covered[i] = 1;
  }
  return s;
}

struct Fixture {
  Scene scene = makeBuiltinScene("sphere-plane");
  std::vector<GeometryInstance> casters = collectInstances(*scene.root, kCastsAO);
  SurfaceSamples points = spherePlanePoints();
  Bounds region = worldBounds(*scene.root);

  AOBuffer reference(Falloff f) {
    EmbreeScene embree(*scene.root);
    ReferenceOptions o;
    o.samples = 16384;
    o.radius = scene.root->aoRadius();
    o.falloff = f;
    return computeReferenceAO(embree, points, o);
  }
};

struct Error {
  double rmse, bias;
};

Error compare(const AOBuffer& a, const AOBuffer& ref) {
  double sq = 0.0, sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < a.ao.size(); ++i) {
    if (!a.covered[i] || !ref.covered[i]) continue;
    const double d = a.ao[i] - ref.ao[i];
    sq += d * d;
    sum += d;
    ++n;
  }
  return {std::sqrt(sq / n), sum / n};
}

HybridSettings settingsFor(int res, int rays, int steps, double offset, Falloff f) {
  HybridSettings s;
  s.gridResolution = res;
  s.memoryBudgetMiB = 256.0;
  s.rays = rays;
  s.steps = steps;
  s.stride = 0.0;  // steps as given: this test varies them
  s.normalOffset = offset;
  s.common.falloff = f;
  return s;
}

struct GridCache {
  Fixture& fx;
  std::map<std::pair<int, bool>, std::pair<VoxelFrame, VoxelGrid>> grids;  // by resolution, solid

  const std::pair<VoxelFrame, VoxelGrid>& grid(int res, bool solid) {
    auto it = grids.find({res, solid});
    if (it != grids.end()) return it->second;
    const VoxelFrame f = VoxelFrame::fitting(fx.region, res);
    return grids.emplace(std::make_pair(res, solid),
                         std::make_pair(f, voxelizeInstances(fx.casters, f, VoxelizeMethod::ThreeAxis, solid)))
        .first->second;
  }
  AOBuffer march(const HybridSettings& s) {
    const auto& [frame, g] = grid(s.gridResolution, s.solid);
    const HybridMarchConstants c = makeHybridMarchConstants(s, frameContext(s.common, fx.scene.root->aoRadius(), Falloff::Binary), frame);
    return marchHybridAO(g, c, fx.points);
  }
  Error error(const HybridSettings& s, const AOBuffer& ref) { return compare(march(s), ref); }
};

// Steps that put samples half a voxel apart: what convergence in resolution needs.
int resolvedSteps(const Fixture& fx, int res) {
  const double voxel = VoxelFrame::fitting(fx.region, res).voxelSize;
  return std::min(256, static_cast<int>(std::ceil(2.0 * fx.scene.root->aoRadius() / voxel)));
}

void header(const std::string& title) {
  std::cout << "\n" << title << "\n  varying  value      rmse      bias\n";
}

void row(const std::string& label, int value, const Error& e, const std::string& note = {}) {
  std::cout << std::setw(10) << label << std::setw(7) << value << std::fixed << std::setprecision(4)
            << std::setw(10) << e.rmse << std::setw(10) << e.bias << note << "\n";
}

}  // namespace

TEST(HybridConvergence, ToTheReferenceAsRaysStepsAndResolutionGrow) {
  Fixture fx;
  GridCache run{fx, {}};
  for (Falloff f : {Falloff::Binary, Falloff::Wendland}) {
    const AOBuffer ref = fx.reference(f);
    const std::string name = f == Falloff::Binary ? "binary" : "wendland";
    const int steps256 = resolvedSteps(fx, 256);
    header("sphere-plane, " + std::to_string(fx.points.width) + " points, R = 1.5, falloff " + name +
           ", three-axis solid grid over the scene, span tests, normal offset 2 voxels; res 256, steps " +
           std::to_string(steps256) + " unless varied");
    std::vector<double> byRays, bySteps, bySeedSteps, byRes;
    for (int rays : {4, 8, 16, 32, 64, 128, 256}) {
      HybridSettings s = settingsFor(256, rays, steps256, 2.0, f);
      const AOBuffer a = run.march(s);
      s.jitterSeed = 12345;
      const double noise = compare(run.march(s), a).rmse / std::sqrt(2.0);  // two independent jitters
      std::ostringstream note;
      note << std::fixed << std::setprecision(4) << "   noise " << noise;
      row("rays", rays, compare(a, ref), note.str());
      byRays.push_back(noise);
    }
    for (int steps : {1, 2, 4, 8, 16, 32, 64, 128, 256}) {
      HybridSettings s = settingsFor(256, 256, steps, 2.0, f);
      const Error e = run.error(s, ref);
      s.spanTest = false;
      const Error point = run.error(s, ref);
      s.solid = false;
      const Error seed = run.error(s, ref);
      std::ostringstream note;
      note << std::fixed << std::setprecision(4) << "   point tests: " << point.rmse << " " << point.bias
           << "   point tests, hollow grid (the seed): " << seed.rmse << " " << seed.bias;
      row("steps", steps, e, note.str());
      bySteps.push_back(e.rmse);
      bySeedSteps.push_back(seed.rmse);
    }
    for (int res : {64, 128, 256, 512, 1024}) {
      const int steps = resolvedSteps(fx, res);
      const Error e = run.error(settingsFor(res, 256, steps, 2.0, f), ref);
      row("res", res, e, "   (steps " + std::to_string(steps) + ")");
      byRes.push_back(e.rmse);
    }
    // Steps: the seed's point tests need steps near R / voxel; span tests get there with 8.
    EXPECT_LT(bySeedSteps.back(), 0.5 * bySeedSteps.front());
    EXPECT_LT(bySteps[3], 0.5 * bySeedSteps[3]);       // 8 steps
    EXPECT_LT(bySteps[3], bySteps.back() + 0.01);      // already at the resolution's limit
    // Everything growing together, from a cheap setting to an expensive one.
    std::vector<double> diagonal;
    for (auto [rays, steps, res] : {std::tuple{8, 4, 64}, {16, 8, 128}, {32, 16, 256}, {64, 32, 512}, {128, 64, 1024}}) {
      const Error e = run.error(settingsFor(res, rays, steps, 2.0, f), ref);
      row("all", res, e, "   (rays " + std::to_string(rays) + ", steps " + std::to_string(steps) + ")");
      diagonal.push_back(e.rmse);
    }
    EXPECT_LT(byRays.back(), 0.25 * byRays.front());  // noise ~ 1/sqrt(rays) or faster: 1/8 expected
    EXPECT_LT(byRes.back(), 0.25 * byRes.front());
    EXPECT_LT(byRes.back(), 0.03);  // res 1024, 256 rays, half-voxel steps
    EXPECT_LT(diagonal.back(), 0.25 * diagonal.front());
    EXPECT_LT(diagonal.back(), 0.03);
  }
}

// Self-occlusion at the voxel scale: surfaces voxelize into cells up to sqrt(3) voxels from them,
// so an origin lifted less than that can start inside its own surface's voxels. Measured on a
// tilted plane alone and on the top of the sphere (true AO 0 on both), against the cost: the error
// at the 42 sphere-plane points.
TEST(HybridConvergence, NormalOffsetTradeOff) {
  Fixture fx;
  GridCache run{fx, {}};
  const AOBuffer ref = fx.reference(Falloff::Binary);

  // A plane tilted off every grid axis, and points on its middle.
  Scene tilted;
  const glm::dmat4 place = rotation(31.0, {1, 0, 0}) * rotation(17.0, {0, 1, 0});
  auto t = std::make_shared<Transform>();
  t->setMatrix(place);
  t->addChild(std::make_shared<Geometry>(makeGridPlane(4.0, 4.0, 8, 8), glm::vec3(1.0f)));
  tilted.root->addChild(t);
  const auto tiltedCasters = collectInstances(*tilted.root, kCastsAO);
  const glm::vec3 tiltedNormal(glm::normalize(glm::dvec3(place * glm::dvec4(0, 0, 1, 0))));
  std::vector<glm::vec3> tiltedPoints, capPoints, capNormals;
  for (int i = 0; i < 64; ++i) {
    const glm::dvec3 local(-1.0 + 2.0 * ((i * 37) % 64) / 63.0, -1.0 + 2.0 * i / 63.0, 0.0);
    tiltedPoints.emplace_back(glm::dvec3(place * glm::dvec4(local, 1.0)));
    const double polar = glm::radians(5.0 + 45.0 * i / 63.0), a = 2.399963 * i;
    const glm::dvec3 n(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a), std::cos(polar));
    capPoints.emplace_back(glm::dvec3(0, 0, 1.2) + n);
    capNormals.emplace_back(n);
  }

  std::cout << "\nnormal offset (voxels) against self-occlusion (mean AO where the truth is 0) and the\n"
            << "error it costs (sphere-plane points, rays 256, half-voxel steps), binary R = 1.5\n"
            << "  res  offset  tilted-plane  sphere-top      rmse      bias\n";
  for (int res : {128, 256}) {
    const int steps = resolvedSteps(fx, res);
    const VoxelFrame tf = VoxelFrame::fitting(worldBounds(*tilted.root), res);
    const VoxelGrid tg = voxelizeInstances(tiltedCasters, tf, VoxelizeMethod::ThreeAxis, true);
    std::vector<double> selfTilted, selfCap, rmse;
    const std::vector<double> offsets = {0.0, 0.5, 1.0, 1.5, 1.75, 2.0, 3.0, 4.0};
    for (double offset : offsets) {
      const HybridSettings s = settingsFor(res, 256, steps, offset, Falloff::Binary);
      const HybridMarchConstants tc = makeHybridMarchConstants(s, frameContext(s.common, 1.5, Falloff::Binary), tf);
      const auto& [frame, grid] = run.grid(res, true);
      const HybridMarchConstants cc = makeHybridMarchConstants(s, frameContext(s.common, 1.5, Falloff::Binary), frame);
      double tiltedAO = 0.0, capAO = 0.0;
      for (std::size_t i = 0; i < tiltedPoints.size(); ++i) {
        tiltedAO += marchHybridAO(tg, tc, tiltedPoints[i], tiltedNormal) / tiltedPoints.size();
        capAO += marchHybridAO(grid, cc, capPoints[i], capNormals[i]) / capPoints.size();
      }
      const Error e = run.error(s, ref);
      std::cout << std::setw(5) << res << std::fixed << std::setprecision(2) << std::setw(8) << offset
                << std::setprecision(4) << std::setw(14) << tiltedAO << std::setw(12) << capAO << std::setw(10)
                << e.rmse << std::setw(10) << e.bias << "\n";
      selfTilted.push_back(tiltedAO);
      selfCap.push_back(capAO);
      rmse.push_back(e.rmse);
    }
    // From 2 voxels (> sqrt 3) on, no self-occlusion on a plane or a convex cap ...
    EXPECT_GT(selfTilted.front(), 0.2);
    EXPECT_LT(selfTilted[5], 1e-3);
    EXPECT_LT(selfCap[5], 1e-3);
    // ... and the error is lowest around there: none and 4 voxels both cost more.
    EXPECT_LT(rmse[5], rmse.back());
    EXPECT_LT(rmse[5], rmse.front());
  }
}
