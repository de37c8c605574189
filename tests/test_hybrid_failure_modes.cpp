// The known failure modes of Hybrid AO (issue 9), charted rather than hidden: each test prints its
// figures (the report quotes them) and checks only the direction the method's design promises.
//   - thin walls: a sheet one voxel thick standing across the grid's x axis is stepped over by
//     long steps (the span test covers the grid's depth axis only); the CPU march, closed form.
//   - the region's boundary: a small region budget cuts the view's far part off; what is cut gets
//     no occlusion.
//   - few rays without the filter: noise; the bilateral filter takes most of it out.
//   - self-occlusion at the voxel scale: without the normal offset a surface's own voxels occlude
//     it; the offset costs occlusion from contacts closer than itself.
// GPU pass on llvmpipe at 256 x 192 against the Embree reference (64 rays per pixel).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/Geometry.h"
#include "headless/FrameCapture.h"
#include "headless/OffscreenWindow.h"
#include "methods/MethodRegistry.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "reference/Falloff.h"
#include "reference/Metrics.h"
#include "render/SceneRenderer.h"
#include "scenes/BuiltinScenes.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"
#include "voxel/CpuVoxelizer.h"
#include "voxel/HybridMarch.h"
#include "voxel/HybridPass.h"
#include "voxel/HybridTechnique.h"

using namespace aokit;

namespace {

constexpr int kW = 256, kH = 192;

BuiltinOptions sourceTreeModels();

struct Rig {
  Scene scene;
  OffscreenWindow window{kW, kH};
  SceneRenderer renderer{window.renderer()};
  SurfaceSamples surfaces;
  AOBuffer reference;
  explicit Rig(const std::string& name) : scene(makeBuiltinScene(name, sourceTreeModels())) {
    renderer.setScene(scene.root);
    renderer.sync();
    renderer.applyCamera(scene.camera);
    surfaces = captureSurfaces(window, renderer);
    EmbreeScene embree(*scene.root);
    reference = computeReferenceAO(embree, surfaces, sceneReferenceOptions(*scene.root, 64, 1));
  }
  // RMSE and mean signed error of the hybrid method with `setting`; the pass for inspection.
  AOErrorMetrics run(const std::string& setting, double* bias = nullptr, VoxelRegion* region = nullptr) {
    auto t = std::dynamic_pointer_cast<HybridTechnique>(makeTechnique("hybrid", setting));
    scene.root->setTechnique(t);
    renderer.sync();
    const AOBuffer ao = captureAO(window, renderer, surfaces.covered);
    if (region) *region = t->pass()->GetRegion();
    scene.root->setTechnique(nullptr);
    renderer.sync();
    if (bias) {
      double sum = 0.0;
      std::size_t n = 0;
      for (std::size_t i = 0; i < ao.ao.size(); ++i)
        if (ao.covered[i] && reference.covered[i]) {
          sum += ao.ao[i] - reference.ao[i];
          ++n;
        }
      *bias = sum / n;
    }
    return compareAO(ao, reference);
  }
};

double ceilingAO(double H, double R) { return 1.0 - H * H / (R * R); }  // binary falloff

BuiltinOptions sourceTreeModels() {
  BuiltinOptions o;
  o.modelsDir = AOKIT_MODELS_DIR;
  return o;
}

}  // namespace

// A wall one voxel thick at distance H in front of the receiver, across the grid's x axis (the
// receiver's normal is +x): point tests and span tests alike test one column per step, so a step
// longer than the wall can land on either side of it, unless stride raises the steps. Across the
// depth axis (a ceiling) the span test catches it (test_hybrid_march.cpp).
TEST(HybridFailureModes, ThinWallsAcrossTheGridsXAxisLeak) {
  const double H = 0.5, R = 1.0;
  Scene s;
  addPlaced(*s.root, makeBox({0.004, 6.0, 6.0}), translation({H + 0.002, 0.0, 0.0}), glm::vec3(1.0f));
  Bounds region;
  region.extend(glm::dvec3(-0.2, -1.5, -1.5));
  region.extend(glm::dvec3(H + 0.6, 1.5, 1.5));
  const VoxelFrame frame = VoxelFrame::fitting(region, 512);
  const VoxelGrid grid = voxelizeInstances(collectInstances(*s.root), frame, VoxelizeMethod::ThreeAxis, true);
  std::printf("wall across x, %.4f thick, voxel %.4f: mean AO of 64 points (closed form %.3f)\n", 0.004,
              frame.voxelSize, ceilingAO(H, R));
  std::printf("  steps   point tests   span tests\n");
  double leakShort = 0.0, leakLong = 0.0;
  for (int steps : {4, 8, 16, 64}) {
    double ao[2];
    for (int span = 0; span < 2; ++span) {
      HybridSettings hs;
      hs.gridResolution = 512;
      hs.rays = 64;
      hs.steps = steps;
      hs.stride = 0.0;  // steps as given
      hs.spanTest = span != 0;
      const HybridMarchConstants c = makeHybridMarchConstants(hs, frameContext(hs.common, R, Falloff::Binary), frame);
      double sum = 0.0;
      for (int i = 0; i < 64; ++i) sum += marchHybridAO(grid, c, glm::vec3(0.0f, 0.013f * i - 0.4f, 0.007f * i), {1, 0, 0});
      ao[span] = sum / 64;
    }
    std::printf("  %5d   %11.3f   %10.3f\n", steps, ao[0], ao[1]);
    if (steps == 4) leakLong = ao[1];
    if (steps == 64) leakShort = ao[1];
  }
  // Long steps leak: most of the wall's occlusion is lost; steps shorter than the voxels close it.
  EXPECT_LT(leakLong, 0.5 * ceilingAO(H, R));
  EXPECT_GT(leakShort, ceilingAO(H, R) - 0.1);
  // stride = 2.5 raises the 8 steps until none crosses more than 2.5 voxels: the wall holds.
  HybridSettings hs;
  hs.gridResolution = 512;
  hs.rays = 64;
  hs.stride = 2.5;
  const HybridMarchConstants c = makeHybridMarchConstants(hs, frameContext(hs.common, R, Falloff::Binary), frame);
  EXPECT_EQ(c.steps, static_cast<int>(std::ceil(R / frame.voxelSize / 2.5)));
  double sum = 0.0;
  for (int i = 0; i < 64; ++i) sum += marchHybridAO(grid, c, glm::vec3(0.0f, 0.013f * i - 0.4f, 0.007f * i), {1, 0, 0});
  std::printf("  stride 2.5 (%d steps): span tests %.3f\n", c.steps, sum / 64);
  EXPECT_GT(sum / 64, ceilingAO(H, R) - 0.05);
  EXPECT_LT(sum / 64, ceilingAO(H, R) + 0.03);
}

// A sheet without thickness (one face, as the open box's walls) is one voxel thick in the grid:
// across x, steps of up to 2.5 voxels still cross it; at most one voxel a step (stride = 1) does
// not. The sheet sits inside a voxel, not on a boundary, so the grid holds it in one layer.
TEST(HybridFailureModes, SheetsWithoutThicknessNeedOneVoxelSteps) {
  const double H = 0.5, R = 1.0;
  Bounds region;
  region.extend(glm::dvec3(-0.2, -1.5, -1.5));
  region.extend(glm::dvec3(H + 0.6, 1.5, 1.5));
  const VoxelFrame frame = VoxelFrame::fitting(region, 512);
  Scene s;
  // The plane's normal +z turned to +x; at the middle of a voxel along x.
  const double x = frame.origin.x + (std::floor((H - frame.origin.x) / frame.voxelSize) + 0.5) * frame.voxelSize;
  addPlaced(*s.root, makeGridPlane(6.0, 6.0, 1, 1), translation({x, 0.0, 0.0}) * rotation(90.0, {0, 1, 0}),
            glm::vec3(1.0f));
  const VoxelGrid grid = voxelizeInstances(collectInstances(*s.root), frame, VoxelizeMethod::ThreeAxis, true);
  auto meanAO = [&](double stride) {
    HybridSettings hs;
    hs.gridResolution = 512;
    hs.rays = 64;
    hs.stride = stride;
    const HybridMarchConstants c = makeHybridMarchConstants(hs, frameContext(hs.common, R, Falloff::Binary), frame);
    double sum = 0.0;
    for (int i = 0; i < 64; ++i) sum += marchHybridAO(grid, c, glm::vec3(0.0f, 0.013f * i - 0.4f, 0.007f * i), {1, 0, 0});
    std::printf("  sheet across x, stride %.1f (%d steps): mean AO %.3f (closed form %.3f)\n", stride, c.steps,
                sum / 64, ceilingAO(x, R));
    return sum / 64;
  };
  EXPECT_LT(meanAO(2.5), ceilingAO(x, R) - 0.1);  // leaks
  const double held = meanAO(1.0);
  EXPECT_GT(held, ceilingAO(x, R) - 0.05);
  EXPECT_LT(held, ceilingAO(x, R) + 0.03);
}

// On the open box (five single faces on a floor), the march over 2.5 voxels a step misses the
// side and back walls from the floor inside (too little AO there); over one voxel it does not.
TEST(HybridFailureModes, OpenBoxWallsHoldWithOneVoxelSteps) {
  Rig rig("open-box");
  double biasLong = 0.0, biasShort = 0.0;
  const AOErrorMetrics longSteps = rig.run("stride=2.5", &biasLong);
  const AOErrorMetrics shortSteps = rig.run("stride=1", &biasShort);
  std::printf("open box: stride 2.5 RMSE %.4f (mean error %+.4f), stride 1 RMSE %.4f (%+.4f)\n", longSteps.rmse,
              biasLong, shortSteps.rmse, biasShort);
  EXPECT_LT(biasLong, -0.005);
  EXPECT_LT(std::abs(biasShort), 0.006);
  EXPECT_LT(shortSteps.rmse, 0.6 * longSteps.rmse);
}

// A region budget smaller than the view: receivers beyond the cut get no occlusion.
TEST(HybridFailureModes, RegionBoundaryCutsOffTheFarField) {
  Rig rig("room");
  std::printf("room: region budget (units of R) -> covered depth, RMSE, mean error\n");
  double tight = 0.0, wide = 0.0;
  for (double budget : {4.0, 8.0, 16.0, 64.0}) {
    double bias = 0.0;
    VoxelRegion region;
    const double rmse = rig.run("region=" + std::to_string(budget), &bias, &region).rmse;
    std::printf("  %5.0f   %6.2f%s   %.4f   %+.4f\n", budget, region.coveredDepth, region.clipped ? " (cut)" : "      ",
                rmse, bias);
    if (budget == 4.0) tight = rmse;
    if (budget == 64.0) wide = rmse;
  }
  EXPECT_GT(tight, wide);
}

// Few rays: the filter takes most of the noise out.
TEST(HybridFailureModes, FewRaysWithoutTheFilter) {
  Rig rig("sphere-plane");
  std::printf("sphere-plane: rays, filter -> RMSE\n");
  const double unfiltered = rig.run("rays=4,window=1").rmse;
  const double filtered = rig.run("rays=4,window=16").rmse;
  const double many = rig.run("rays=64,window=1").rmse;
  std::printf("  4 rays, no filter %.4f; 4 rays, m = 16 %.4f; 64 rays, no filter %.4f\n", unfiltered, filtered, many);
  EXPECT_LT(filtered, 0.6 * unfiltered);
}

// The normal offset: without it, a surface's own voxels occlude it (the error grows with the
// voxel size); a large one loses contact occlusion. Fandisk is closed: its own voxels stand out of
// it only untrimmed (trim=0); trimmed, they end at its surface and occlude it less at offset 0.
TEST(HybridFailureModes, SelfOcclusionAtTheVoxelScale) {
  for (const char* name : {"sphere-plane", "fandisk"}) {
    if (std::string(name) == "fandisk" &&
        !std::filesystem::exists(std::filesystem::path(AOKIT_MODELS_DIR) / "packaged" / "fandisk.off")) {
      std::printf("fandisk skipped: run models/fetch-meshes.sh\n");
      continue;
    }
    Rig rig(name);
    const std::string trim = std::string(name) == "fandisk" ? "trim=0," : "";
    std::printf("%s: normal offset (voxels) -> RMSE, mean error, at res 128 and 256 (%s)\n", name,
                trim.empty() ? "defaults" : "untrimmed");
    double at0 = 0.0, at2 = 0.0;
    for (double offset : {0.0, 0.5, 1.0, 2.0, 3.0, 4.0}) {
      std::printf("  %.1f", offset);
      for (int res : {128, 256}) {
        double bias = 0.0;
        const double rmse =
            rig.run(trim + "res=" + std::to_string(res) + ",offset=" + std::to_string(offset), &bias).rmse;
        std::printf("   %.4f %+.4f", rmse, bias);
        if (res == 256 && offset == 0.0) at0 = rmse;
        if (res == 256 && offset == 2.0) at2 = rmse;
      }
      std::printf("\n");
    }
    EXPECT_LT(at2, at0) << name;
    if (!trim.empty()) {
      double bias0 = 0.0, trimmedBias0 = 0.0;
      rig.run(trim + "res=256,offset=0", &bias0);
      const double trimmed0 = rig.run("res=256,offset=0", &trimmedBias0).rmse;
      std::printf("  trimmed, offset 0, res 256: %.4f %+.4f\n", trimmed0, trimmedBias0);
      EXPECT_LT(trimmed0, at0) << name;
      EXPECT_LT(trimmedBias0, bias0) << name;  // less self-occlusion
    }
  }
}
