// HybridPass on llvmpipe: the GPU pipeline against its CPU oracle computeHybridAOCpu on the very
// G-buffer the pass rendered (grid voxel for voxel, AO to round-off), and against the Embree
// reference on the scenes the method exists for; the region of interest kept across frames; a
// plain VTK pipeline; bad settings; the voxel view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "core/Geometry.h"
#include "headless/FrameCapture.h"
#include "headless/OffscreenWindow.h"
#include "methods/MethodRegistry.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "reference/Metrics.h"
#include "render/SceneRenderer.h"
#include "scenes/BuiltinScenes.h"
#include "voxel/ColumnWalk.h"
#include "voxel/CpuVoxelizer.h"
#include "voxel/HybridCpu.h"
#include "voxel/HybridPass.h"
#include "voxel/HybridTechnique.h"
#include "test_hybrid_rig.h"

using namespace aokit;
using namespace aokit::hybridtest;

namespace {

// The grid the CPU voxelizer makes over the same region and casters.
VoxelGrid cpuGrid(Scene& s, const VoxelRegion& region, const HybridSettings& hs) {
  const auto all = collectInstances(*s.root, kCastsAO);
  std::vector<GeometryInstance> casters;
  for (std::size_t i : region.casters) casters.push_back(all[i]);
  return voxelizeInstances(casters, region.frame, voxelizeMethodFor(hs.frame), hs.solid, {}, hs.trimShell);
}

}  // namespace

// The GPU pass and the CPU oracle on the G-buffer the pass drew: same region, the same grid but
// for round-off voxels, and the same AO but where float round-off moves a ray across a voxel
// boundary (then one ray differs: 1/16 of the AO with the default 16 rays, before filtering).
TEST(HybridPass, MatchesTheCpuOracleOnItsOwnGBuffer) {
  struct Case {
    const char* scene;
    const char* setting;
  };
  const Case cases[] = {{"sphere-plane", ""},     {"sphere-offscreen", ""},          {"hidden", ""},
                        {"behind", ""},           {"sphere-plane", "scale=0.25,window=32"}, {"sphere-plane", "scale=0.25,window=1"}, {"sphere-plane", "scale=0.25,window=8"}, {"sphere-plane", "window=8"},
                        {"cubes", "frame=dominant,falloff=wendland,spread=0.7"},
                        {"room", "frame=rotated,span=0,solid=0,window=1"},
                        {"cubes", "lift=ray"},  {"isosurface", "segment=1"},  {"hidden", "segment=1,lift=ray"},  {"hidden", "lift=graze,reach=2"},  // rays from the surface, creases as normal
                        {"hidden", "rays=256,steps=128,res=512,scale=0.25,window=32"}};  // two march passes
  std::printf("GPU against CPU oracle on the pass's own G-buffer: grid voxels differing / set; AO |diff| mean, "
              "p99, max, share > 0.05\n");
  for (const Case& c : cases) {
    SCOPED_TRACE(std::string(c.scene) + " " + c.setting);
    SceneRig rig(c.scene);
    auto t = std::dynamic_pointer_cast<HybridTechnique>(makeTechnique("hybrid", c.setting));
    rig.scene.root->setTechnique(t);
    rig.renderer.sync();
    const AOBuffer gpu = rig.render(*t);
    HybridPass* pass = t->pass();
    const HybridSettings& hs = t->settings();
    const SurfaceSamples lean = leanSurfaces(pass, rig.window.renderer());
    const HybridCpuResult cpu = computeHybridAOCpu(*rig.scene.root, rig.scene.camera, lean, rig.scene.root->aoRadius(),
                                                   rig.scene.root->falloff(), hs);
    ASSERT_FALSE(pass->GetRegion().empty);
    EXPECT_EQ(pass->GetRegion().frame.dims, cpu.region.frame.dims);
    EXPECT_EQ(pass->GetRegion().frame.voxelSize, cpu.region.frame.voxelSize);
    EXPECT_LT(glm::distance(pass->GetRegion().frame.origin, cpu.region.frame.origin), 1e-9);
    EXPECT_EQ(pass->GetRegion().casters, cpu.region.casters);
    VoxelGrid grid;
    ASSERT_TRUE(pass->ReadGrid(rig.window.window(), grid));
    const VoxelGrid expected = cpuGrid(rig.scene, cpu.region, hs);
    const std::size_t wrongVoxels = grid.count() + expected.count() - 2 * intersectionCount(grid, expected);
    const Difference d = differ(gpu, cpu.ao);
    std::printf("  %-16s %-42s %6zu / %8zu   %.5f %.4f %.4f %.4f\n", c.scene, c.setting, wrongVoxels, expected.count(),
                d.mean, d.p99, d.max, d.over05);
    EXPECT_LE(wrongVoxels, expected.count() / 10000 + 8);
    EXPECT_LT(d.mean, 0.002);
    EXPECT_LT(d.p99, 0.03);
    EXPECT_LT(d.over05, 0.003);
    rig.detach();
  }
}

// Against the reference: the occluder hidden behind a panel, behind the camera or off screen is
// seen as well as the one in view (the target is RMSE <= 1.2 x sphere-plane's; here at
// 256 x 192 with a 64-ray reference, whose own noise adds about 0.02 in quadrature).
TEST(HybridPass, SeesOccludersTheScreenDoesNotShow) {
  std::printf("hybrid (defaults) against the Embree reference (64 rays/pixel), %d x %d: RMSE, ratio to sphere-plane\n",
              kW, kH);
  auto rmseOf = [](const char* name) {
    SceneRig rig(name);
    const AOBuffer ref = rig.reference();
    auto t = rig.attach(HybridSettings{});
    const double rmse = compareAO(rig.render(*t), ref).rmse;
    rig.detach();
    return rmse;
  };
  const double base = rmseOf("sphere-plane");  // the occluder in view: the yardstick, not a case
  std::printf("  %-16s %.4f\n", "sphere-plane", base);
  EXPECT_LT(base, 0.06);
  for (const char* name : {"sphere-offscreen", "hidden", "behind"}) {
    const double rmse = rmseOf(name);
    std::printf("  %-16s %.4f  %.2f\n", name, rmse, rmse / base);
    EXPECT_LT(rmse, 0.06) << name;
    EXPECT_LT(rmse, 1.6 * base) << name;
  }
}

// Techniques live across frames: the region is computed again only when the camera or a caster
// moves, a mesh is uploaded once, and every frame is voxelized.
TEST(HybridPass, RecomputesOnlyWhatChanged) {
  SceneRig rig("animated");
  auto t = rig.attach(HybridSettings{});
  rig.window.render();
  rig.window.render();
  HybridPass* pass = t->pass();
  EXPECT_EQ(pass->GetRegionComputations(), 1);
  const std::size_t uploads = pass->GetCasterUploads();
  EXPECT_GT(uploads, 0u);
  EXPECT_GT(pass->GetVoxelizedCasters(), 0u);
  rig.scene.animate(rig.scene, 3);  // moves transforms and the camera
  rig.renderer.sync();
  rig.renderer.applyCamera(rig.scene.camera);
  rig.window.render();
  EXPECT_EQ(pass->GetRegionComputations(), 2);
  EXPECT_EQ(pass->GetCasterUploads(), uploads) << "a moved transform must not upload its mesh again";
  rig.window.render();
  EXPECT_EQ(pass->GetRegionComputations(), 2);
  rig.detach();
}

TEST(HybridPass, WorksInAPlainVtkPipeline) {
  OffscreenWindow window(kW, kH);
  vtkRenderer* renderer = window.renderer();
  vtkNew<vtkSphereSource> sphere;  // triangle strips? no: polys; the plane is one quad
  sphere->SetCenter(0, 0, 1.2);
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-4, -4, 0);
  plane->SetPoint1(4, -4, 0);
  plane->SetPoint2(-4, 4, 0);
  for (vtkAlgorithm* src : {static_cast<vtkAlgorithm*>(sphere), static_cast<vtkAlgorithm*>(plane)}) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(src->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
  }
  renderer->GetActiveCamera()->SetPosition(0, -6.5, 4.0);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0.7);
  renderer->GetActiveCamera()->SetViewUp(0, 0, 1);
  renderer->ResetCameraClippingRange();
  vtkNew<HybridPass> pass;  // radius from the visible bounds
  renderer->SetPass(pass);
  window.render();
  EXPECT_EQ(pass->GetVoxelizedCasters(), 2u);
  std::vector<float> ao;
  ASSERT_TRUE(pass->ReadAO(window.window(), ao));
  for (float v : ao) ASSERT_TRUE(v >= 0.0f && v <= 1.0f);
  int below = -1;  // the floor under the sphere is occluded
  for (int y = kH / 2; y > 0 && below < 0; --y)
    if (ao[y * kW + kW / 2] > 0.3f) below = y;
  EXPECT_GT(below, 0);
  EXPECT_LT(ao[2 * kW + kW / 2], 0.1f);  // the floor near the frame's bottom is open
  EXPECT_GT(pass->MemoryBytes(), pass->GetRegion().memoryBytes);
  renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(window.window());
}

// llvmpipe ends an invocation's loops after 65535 iterations: heavy settings march in passes.
TEST(HybridPass, RaysPerMarchPassStayWithinTheLoopBudget) {
  HybridMarchConstants c;
  c.worldToGrid = glm::mat4(1.0f / 0.01f);  // voxels of 0.01
  c.worldToGrid[3][3] = 1.0f;
  c.dims = glm::ivec3(256);
  c.radius = 1.5f;
  c.rays = 32;
  c.steps = 8;  // steps of 19 voxels: one or two words each
  EXPECT_EQ(raysPerMarchPass(c, true), 32);
  c.rays = 256;
  c.steps = 256;
  const int n = raysPerMarchPass(c, true);
  EXPECT_LT(n, 256);
  EXPECT_GT(n, 16);
  EXPECT_LE(n * (2 + 256 * 3) + 2 * 256, 65535);
  c.steps = 1;  // one step of 150 voxels: up to 8 words of the column
  EXPECT_LE(raysPerMarchPass(c, true) * (2 + 1 * (1 + 8)) + 512, 65535);
  // The segment test's walk: a ray of 150 voxels passes at most 150 sqrt 2 + 3 columns, each one
  // loop iteration and its run's words (all runs together 150 voxels of depth and one more a
  // column: at most one word a column beyond 150 / 32 + 1), then up to 9 words for the first hit.
  c.segmentTest = true;
  c.walkColumns = columnWalkBound(150.0);
  EXPECT_GE(c.walkColumns, 150.0 * std::sqrt(2.0) + 3.0);
  const int walkRays = raysPerMarchPass(c, true);
  EXPECT_GT(walkRays, 16);
  EXPECT_LE(walkRays * (2 + c.walkColumns + (c.walkColumns + 150 / 32 + 1) + 9) + 512, 65535);
  EXPECT_EQ(raysPerMarchPass(c, false), 256);
}

TEST(HybridPass, BadSettingsFailInOneLineBeforeAnyAllocation) {
  for (const char* bad : {"rays=0", "steps=0", "res=1024", "res=512,budget=8", "hn=0",
                          "bx0=1,by0=0,bz0=0", "bx0=1,by0=0,bz0=0,bx1=0,by1=1,bz1=1"}) {
    try {
      makeTechnique("hybrid", bad);
      ADD_FAILURE() << bad << " was accepted";
    } catch (const std::invalid_argument& e) {
      const std::string msg = e.what();
      EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
      EXPECT_NE(msg.find("hybrid"), std::string::npos) << msg;
    }
  }
  EXPECT_NO_THROW(makeTechnique("hybrid", "res=1024,budget=128"));
}

// The voxel view shows the grid: the sphere's voxels where the sphere is, the floor's below, as grey
// over the whole frame: a voxel face (0.55, 0.75 or 0.95 by axis, dimmed by at most half with
// distance) where a surface is, the empty grid (0.12) or nothing (0) on most of the background. The
// lit frame (the fallback when the view fails) has the renderer's bluish background, so it cannot pass.
TEST(HybridPass, VoxelView) {
  SceneRig rig("sphere-plane");
  HybridSettings s;
  s.common.view = DebugView::Voxels;
  s.gridResolution = 64;
  rig.attach(s);
  rig.window.render();
  const RGBAImage img = rig.window.readColor();
  rig.detach();
  std::size_t lit = 0, covered = 0, grey = 0, background = 0, emptyOrOutside = 0;
  for (std::size_t i = 0; i < rig.surfaces.pixelCount(); ++i) {
    const int r = img.pixels[4 * i], g = img.pixels[4 * i + 1], b = img.pixels[4 * i + 2];
    grey += std::abs(r - g) <= 1 && std::abs(r - b) <= 1;
    if (rig.surfaces.covered[i]) {
      ++covered;
      lit += r > 60;  // a voxel face
    } else {
      ++background;
      emptyOrOutside += r <= 1 || std::abs(r - 31) <= 1;  // 0, or 0.12 * 255
    }
  }
  ASSERT_GT(background, 0u);
  EXPECT_GT(double(lit) / covered, 0.95);
  EXPECT_EQ(grey, rig.surfaces.pixelCount());
  // Background rays may still hit the conservative voxels beside a silhouette; most meet none.
  EXPECT_GT(double(emptyOrOutside) / background, 0.8);
}
