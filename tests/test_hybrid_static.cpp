// Hybrid AO with static plus dynamic (issue 9 item 5, HybridSettings::staticBake) on llvmpipe:
// the G-buffer's dynamic flag, the GPU pass against its CPU oracle on its own G-buffer (baked
// values read back from it), the whole against the Embree reference on `courtyard` beside hybrid
// without the split and beside a variant that counts static occluders twice, a scene that is all
// static, plain VTK props, and the bake's life on the actors.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCubeSource.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkSphereSource.h>

#include "core/Geometry.h"
#include "methods/MethodRegistry.h"
#include "reference/Metrics.h"
#include "render/ActorKeys.h"
#include "render/BakedAO.h"
#include "voxel/HybridCpu.h"
#include "voxel/StaticProps.h"
#include "test_hybrid_rig.h"

using namespace aokit;
using namespace aokit::hybridtest;

namespace {

constexpr int kFlagReceives = 2, kFlagDynamic = 8;  // ActorKeys.h, DeferredCommon.glsl

HybridSettings staticSettings(int bakeRays = 64) {
  HybridSettings s;
  s.staticBake = true;
  s.bakeRays = bakeRays;
  return s;
}

std::vector<std::uint8_t> readFlags(HybridPass* pass) {
  std::vector<std::uint8_t> flags;
  EXPECT_TRUE(pass->GetGBufferPass()->ReadFlags(flags));
  return flags;
}

// The G-buffer's baked AO target (R16F), one float per pixel (no guard band in this pass).
std::vector<float> readBaked(HybridPass* pass) {
  vtkTextureObject* t = pass->GetGBufferPass()->GetBakedAOTexture();
  std::vector<float> v(static_cast<std::size_t>(t->GetWidth()) * t->GetHeight());
  glGetTextureImage(t->GetHandle(), 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(v.size() * 4), v.data());
  return v;
}

// The AO of `a` on the pixels where keep(i) holds.
template <class Keep>
AOBuffer only(const AOBuffer& a, Keep keep) {
  AOBuffer out = a;
  for (std::size_t i = 0; i < out.covered.size(); ++i) out.covered[i] = a.covered[i] && keep(i);
  return out;
}

double bias(const AOBuffer& a, const AOBuffer& ref) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < a.ao.size(); ++i)
    if (a.covered[i] && ref.covered[i]) {
      sum += a.ao[i] - ref.ao[i];
      ++n;
    }
  return n ? sum / n : 0.0;
}

Node* findNamed(Node& root, const std::string& name) {
  struct Finder : NodeVisitor {
    std::string name;
    Node* found = nullptr;
    void apply(Group& g) override {
      if (!found && g.name() == name) found = &g;
      NodeVisitor::apply(g);
    }
  } f;
  f.name = name;
  root.accept(f);
  return f.found;
}

std::size_t actorsWithBake(vtkRenderer* renderer) {
  std::size_t n = 0;
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor()) n += hasBakedAO(a) ? 1 : 0;
  return n;
}

}  // namespace

// Flag 8 follows the node mask along the path (the courtyard's static group clears it), and a
// plain VTK prop is dynamic until setPropDynamic says otherwise.
TEST(HybridStatic, TheGBufferTellsStaticFromDynamicReceivers) {
  SceneRig rig("courtyard");
  auto t = rig.attach(staticSettings(8));
  rig.render(*t);
  std::vector<std::uint8_t> flags = readFlags(t->pass());
  int dynamicPixels = 0, staticPixels = 0;
  for (std::size_t i = 0; i < flags.size(); ++i)
    if (rig.surfaces.covered[i]) (flags[i] & kFlagDynamic ? dynamicPixels : staticPixels)++;
  std::printf("courtyard %d x %d: %d static pixels, %d dynamic\n", kW, kH, staticPixels, dynamicPixels);
  EXPECT_GT(staticPixels, 10 * dynamicPixels);
  EXPECT_GT(dynamicPixels, 500);
  rig.scene.root->setDynamic(false);  // now everything
  rig.renderer.sync();
  rig.render(*t);
  flags = readFlags(t->pass());
  for (std::size_t i = 0; i < flags.size(); ++i) ASSERT_EQ(flags[i] & kFlagDynamic, 0) << i;
  rig.detach();

  vtkNew<vtkActor> actor;
  EXPECT_TRUE(propDynamic(actor));
  setPropDynamic(actor, false);
  EXPECT_FALSE(propDynamic(actor));
  EXPECT_TRUE(propCastsAO(actor));  // the other keys keep their defaults
  tagProp(actor, kDefaultMask, 7);
  EXPECT_TRUE(propDynamic(actor));
  tagProp(actor, kDefaultMask & ~kDynamic, 7);
  EXPECT_FALSE(propDynamic(actor));
}

// The GPU pass against computeHybridAOCpu in static mode on the pass's own G-buffer (its flags say
// which receivers are dynamic), combined with the baked values the G-buffer carried, as the
// combine stage does: same region and zones, same AO but for float round-off.
TEST(HybridStatic, MatchesTheCpuOracleOnItsOwnGBuffer) {
  std::printf("static mode, GPU against CPU oracle: AO |diff| mean, p99, max, share > 0.05\n");
  for (const char* setting : {"static=1,bakerays=32", "static=1,bakerays=32,scale=0.25,window=12,rays=12,steps=5"}) {
    SCOPED_TRACE(setting);
    SceneRig rig("courtyard");
    auto t = std::dynamic_pointer_cast<HybridTechnique>(makeTechnique("hybrid", setting));
    rig.scene.root->setTechnique(t);
    rig.renderer.sync();
    const AOBuffer gpu = rig.render(*t);
    HybridPass* pass = t->pass();
    const SurfaceSamples lean = leanSurfaces(pass, rig.window.renderer());
    const std::vector<std::uint8_t> flags = readFlags(pass);
    const std::vector<float> baked = readBaked(pass);
    std::vector<std::uint8_t> dynamicReceivers(flags.size());
    for (std::size_t i = 0; i < flags.size(); ++i) dynamicReceivers[i] = (flags[i] & kFlagDynamic) ? 1 : 0;
    const HybridCpuResult cpu = computeHybridAOCpu(*rig.scene.root, rig.scene.camera, lean, rig.scene.root->aoRadius(),
                                                   rig.scene.root->falloff(), t->settings(), dynamicReceivers);
    ASSERT_FALSE(pass->GetRegion().empty);
    EXPECT_EQ(pass->GetRegion().frame.dims, cpu.region.frame.dims);
    EXPECT_LT(glm::distance(pass->GetRegion().frame.origin, cpu.region.frame.origin), 1e-9);
    EXPECT_EQ(pass->GetDynamicZones().size(), cpu.plan.zones.size());
    EXPECT_EQ(pass->GetVoxelizedCasters(), cpu.plan.allCasters.size());
    EXPECT_EQ(pass->GetVoxelizedStaticCasters(), cpu.plan.staticCasters.size());
    AOBuffer combined = cpu.ao;
    for (std::size_t i = 0; i < combined.ao.size(); ++i)
      combined.ao[i] = (flags[i] & kFlagReceives) ? combineBakedAndDynamic(baked[i], cpu.ao.ao[i]) : 0.0f;
    const Difference d = differ(gpu, combined);
    std::printf("  %-58s %.5f %.4f %.4f %.4f\n", setting, d.mean, d.p99, d.max, d.over05);
    EXPECT_LT(d.mean, 0.002);
    EXPECT_LT(d.p99, 0.03);
    EXPECT_LT(d.over05, 0.003);
    rig.detach();
  }
}

// Against the reference (256 rays per pixel) on the courtyard: static plus dynamic, hybrid alone,
// and the split done wrong (static receivers marching every caster on top of their bake, from the
// CPU oracle with every receiver flagged dynamic). Dynamic receivers must see the static
// occluders: closer to the whole reference than to the reference of the dynamic casters alone.
TEST(HybridStatic, CourtyardAgainstTheReference) {
  SceneRig rig("courtyard");
  const AOBuffer ref = rig.reference(256);
  auto plain = rig.attach(HybridSettings{});
  const AOBuffer hybrid = rig.render(*plain);
  rig.detach();
  auto t = rig.attach(staticSettings(128));
  const AOBuffer split = rig.render(*t);
  HybridPass* pass = t->pass();
  const std::vector<std::uint8_t> flags = readFlags(pass);
  const std::vector<float> baked = readBaked(pass);
  const SurfaceSamples lean = leanSurfaces(pass, rig.window.renderer());
  const VoxelRegion region = pass->GetRegion();
  const HybridCpuResult twice = computeHybridAOCpu(*rig.scene.root, rig.scene.camera, lean, rig.scene.root->aoRadius(),
                                                   rig.scene.root->falloff(), t->settings(),
                                                   std::vector<std::uint8_t>(flags.size(), 1));
  AOBuffer doubled = split;
  for (std::size_t i = 0; i < doubled.ao.size(); ++i)
    doubled.ao[i] = (flags[i] & kFlagReceives) ? combineBakedAndDynamic(baked[i], twice.ao.ao[i]) : 0.0f;
  rig.detach();
  Node* statics = findNamed(*rig.scene.root, "static");
  ASSERT_NE(statics, nullptr);
  statics->setMask(statics->mask() & ~std::uint32_t(kCastsAO));
  const AOBuffer dynamicOnlyRef = rig.reference(256);
  statics->setMask(statics->mask() | kCastsAO);

  auto isStatic = [&](std::size_t i) { return (flags[i] & kFlagDynamic) == 0; };
  auto isDynamic = [&](std::size_t i) { return (flags[i] & kFlagDynamic) != 0; };
  std::printf("courtyard %d x %d against the reference (256 rays): rmse all / static px (bias) / dynamic px\n", kW, kH);
  auto row = [&](const char* name, const AOBuffer& a) {
    std::printf("  %-34s %.4f  %.4f (%+.4f)  %.4f\n", name, compareAO(a, ref).rmse, compareAO(only(a, isStatic), ref).rmse,
                bias(only(a, isStatic), ref), compareAO(only(a, isDynamic), ref).rmse);
  };
  row("hybrid (defaults)", hybrid);
  row("static=1 (baked + dynamic)", split);
  row("static counted twice (CPU)", doubled);
  const double rmse = compareAO(split, ref).rmse, staticBias = bias(only(split, isStatic), ref);
  EXPECT_LT(rmse, 0.03);
  EXPECT_LT(rmse, 0.7 * compareAO(hybrid, ref).rmse);
  EXPECT_LT(std::abs(staticBias), 0.01);
  // Where the bake holds some occlusion, inside the grid (the CPU variant marches there only),
  // counting it twice shows as a bias.
  auto staticOccluded = [&](std::size_t i) {
    const glm::dvec3 p(rig.surfaces.position[i]);
    const Bounds& box = region.box;
    return isStatic(i) && baked[i] > 0.1f && glm::all(glm::greaterThanEqual(p, box.min)) &&
           glm::all(glm::lessThanEqual(p, box.max));
  };
  const double onceBias = bias(only(split, staticOccluded), ref), twiceBias = bias(only(doubled, staticOccluded), ref);
  std::printf("  static pixels in the grid with baked AO > 0.1: bias %+.4f, counted twice %+.4f\n", onceBias, twiceBias);
  EXPECT_LT(std::abs(onceBias), 0.015);
  EXPECT_GT(twiceBias, onceBias + 0.04);
  EXPECT_GT(compareAO(only(doubled, isStatic), ref).rmse, 2.0 * compareAO(only(split, isStatic), ref).rmse);
  const double toWhole = compareAO(only(split, isDynamic), ref).rmse;
  const double toDynamicOnly = compareAO(only(split, isDynamic), dynamicOnlyRef).rmse;
  std::printf("  dynamic receivers: rmse to the whole reference %.4f, to the dynamic casters' alone %.4f\n", toWhole,
              toDynamicOnly);
  EXPECT_LT(toWhole, 0.6 * toDynamicOnly);
}

// Nothing dynamic: no grid, no march, the frame's AO is the bake alone, and it counts each
// static occluder once.
TEST(HybridStatic, AllStaticIsTheBakeAlone) {
  SceneRig rig("courtyard");
  rig.scene.root->setDynamic(false);
  const AOBuffer ref = rig.reference(256);
  auto t = rig.attach(staticSettings(128));
  const AOBuffer ao = rig.render(*t);
  EXPECT_TRUE(t->pass()->GetRegion().empty);
  EXPECT_EQ(t->pass()->GetVoxelizedCasters(), 0u);
  const double rmse = compareAO(ao, ref).rmse, b = bias(ao, ref);
  std::printf("courtyard, all static: bake alone against the reference: rmse %.4f, bias %+.4f\n", rmse, b);
  EXPECT_LT(rmse, 0.03);
  EXPECT_LT(std::abs(b), 0.01);
  rig.detach();
}

// The technique puts the bake on its actors and takes it off when detached; memory counts it.
TEST(HybridStatic, TheBakeLivesWithTheTechnique) {
  SceneRig rig("courtyard");
  auto t = rig.attach(staticSettings(8));
  rig.render(*t);
  const std::size_t staticReceivers = t->staticBake().perInstance.size();
  EXPECT_EQ(staticReceivers, 10u);  // floor, 3 walls, 4 pillars, bench, planter
  EXPECT_EQ(actorsWithBake(rig.window.renderer()), staticReceivers);
  EXPECT_GE(t->memoryBytes(), t->staticBake().memoryBytes() + t->pass()->GetRegion().memoryBytes);
  rig.detach();
  EXPECT_EQ(actorsWithBake(rig.window.renderer()), 0u);
  auto off = rig.attach(HybridSettings{});  // static off: nothing baked, no baked target
  rig.render(*off);
  EXPECT_EQ(actorsWithBake(rig.window.renderer()), 0u);
  EXPECT_EQ(off->pass()->GetGBufferPass()->GetBakedAOTexture(), nullptr);
  rig.detach();
}

// Plain VTK: props marked static are baked by bakeStaticProps and the pass marches the rest.
TEST(HybridStatic, PlainVtkProps) {
  OffscreenWindow window(kW, kH);
  vtkRenderer* renderer = window.renderer();
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-4, -4, 0);
  plane->SetPoint1(4, -4, 0);
  plane->SetPoint2(-4, 4, 0);
  plane->SetResolution(32, 32);
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(-2.0, 0.0, 0.5);
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(1.5, 0, 1.2);
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  vtkActor* actors[3];
  int k = 0;
  for (vtkAlgorithm* src : {static_cast<vtkAlgorithm*>(plane), static_cast<vtkAlgorithm*>(cube),
                            static_cast<vtkAlgorithm*>(sphere)}) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(src->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->AddActor(actor);
    actors[k++] = actor;
  }
  setPropDynamic(actors[0], false);
  setPropDynamic(actors[1], false);
  renderer->GetActiveCamera()->SetPosition(0, -7.5, 5.0);
  renderer->GetActiveCamera()->SetFocalPoint(0, 0, 0.5);
  renderer->GetActiveCamera()->SetViewUp(0, 0, 1);
  renderer->ResetCameraClippingRange();
  StaticBakeOptions bake;
  bake.radius = 1.0;
  bake.rays = 64;
  EXPECT_EQ(bakeStaticProps(renderer, bake), 2u);
  EXPECT_TRUE(hasBakedAO(actors[0]));
  EXPECT_TRUE(hasBakedAO(actors[1]));
  EXPECT_FALSE(hasBakedAO(actors[2]));
  vtkNew<HybridPass> pass;
  HybridSettings s = staticSettings();
  s.common.radius = 1.0;
  pass->SetSettings(s);
  renderer->SetPass(pass);
  window.render();
  EXPECT_EQ(pass->GetVoxelizedCasters(), 2u);  // the sphere, and the floor under it
  EXPECT_EQ(pass->GetVoxelizedStaticCasters(), 1u);
  std::vector<float> ao;
  ASSERT_TRUE(pass->ReadAO(window.window(), ao));
  auto aoAt = [&](double x, double y, double z) {
    renderer->SetWorldPoint(x, y, z, 1.0);
    renderer->WorldToDisplay();
    const double* d = renderer->GetDisplayPoint();
    const int px = static_cast<int>(d[0]), py = static_cast<int>(d[1]);
    if (px < 0 || py < 0 || px >= kW || py >= kH || ao.size() != static_cast<std::size_t>(kW) * kH) {
      ADD_FAILURE() << "(" << px << ", " << py << ") outside the " << kW << " x " << kH << " AO image of " << ao.size();
      return -1.0f;
    }
    return ao[static_cast<std::size_t>(py) * kW + static_cast<std::size_t>(px)];
  };
  EXPECT_GT(aoAt(-2.0, -0.55, 0.0), 0.3f);  // the floor at the cube's foot: baked
  EXPECT_GT(aoAt(1.5, -0.3, 0.0), 0.3f);    // under the sphere: marched
  EXPECT_LT(aoAt(0.0, -2.5, 0.0), 0.05f);   // open floor, farther than R from both (in view)
  renderer->SetPass(nullptr);
  pass->ReleaseGraphicsResources(window.window());
}

// The bake is made once; the objects and the camera move on, and the zones and grids follow them.
TEST(HybridStatic, MovingFramesKeepTheBakeAndFollowTheMovers) {
  SceneRig rig("courtyard");
  auto t = rig.attach(staticSettings(128));
  rig.render(*t);
  const float* firstValues = t->staticBake().perInstance.begin()->second.data();
  std::printf("courtyard frames with one bake: frame, rmse against the reference (128 rays)\n");
  for (int frame : {12, 37}) {
    rig.scene.animate(rig.scene, frame);
    rig.renderer.sync();
    rig.renderer.applyCamera(rig.scene.camera);
    rig.surfaces = captureSurfaces(rig.window, rig.renderer);
    const AOBuffer ref = rig.reference(128);
    const double rmse = compareAO(rig.render(*t), ref).rmse;
    std::printf("  %2d  %.4f\n", frame, rmse);
    EXPECT_LT(rmse, 0.035) << frame;
  }
  // Capturing the surfaces swapped the technique out and back: the same bake went back on.
  EXPECT_EQ(t->staticBake().perInstance.begin()->second.data(), firstValues) << "baked once";
  EXPECT_EQ(actorsWithBake(rig.window.renderer()), 10u);
  rig.detach();
}

TEST(HybridStatic, BadSettingsFailInOneLine) {
  HybridSettings s = staticSettings(0);
  try {
    validate(s);
    FAIL() << "bakeRays 0 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "hybrid: bakerays must be an integer in 1..4096, got 0");
  }
  EXPECT_THROW(makeTechnique("hybrid", "static=1,bakerays=5000"), std::invalid_argument);
  StaticBakeOptions o;
  o.rays = 0;
  Scene scene = makeBuiltinScene("courtyard");
  EXPECT_THROW(bakeStaticInstances(*scene.root, o), std::invalid_argument);
  o.rays = 8;
  o.radius = -1.0;
  EXPECT_THROW(bakeStaticInstances(*scene.root, o), std::invalid_argument);
}
