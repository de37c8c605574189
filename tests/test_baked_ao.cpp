// Per-vertex baked AO through the G-buffer: values set on an actor reach the frame interpolated
// across its triangles, other actors read 0, and clearing them restores 0.
#include <set>

#include <gtest/gtest.h>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "core/BakeRefinement.h"
#include "core/CreaseSplit.h"
#include "core/Geometry.h"
#include "core/NodeVisitor.h"
#include "headless/FrameCapture.h"
#include "headless/SceneView.h"
#include "render/ActorKeys.h"
#include "render/BakedAO.h"
#include "render/DeferredAOPass.h"
#include "scenes/BuiltinScenes.h"

using namespace aokit;

namespace {

// A deferred pass whose own AO is 0 everywhere: what reaches the frame is the baked AO alone.
class BakedOnlyPass : public DeferredAOPass {
 public:
  static BakedOnlyPass* New();
  vtkTypeMacro(BakedOnlyPass, DeferredAOPass);

 protected:
  const DeferredSettings& CommonSettings() const override { return Common; }
  void Plan(const FrameContext&, DeferredPlan& plan) override { plan.config.bakedAO = true; }
  vtkTextureObject* RenderAO(DeferredFrame& f) override {
    f.fbo->Bind();
    f.fbo->AddColorAttachment(0, f.aoTarget);
    f.fbo->ActivateDrawBuffers(1);
    const float zero[4] = {0, 0, 0, 0};
    glClearBufferfv(GL_COLOR, 0, zero);
    f.fbo->RemoveColorAttachment(0);
    f.fbo->UnBind();
    return f.aoTarget;
  }

 private:
  DeferredSettings Common = deferredDefaults(AOScale::Full);
};
vtkStandardNewMacro(BakedOnlyPass);

// A cube 1.2 across whose eight corners are shared vertices, its faces in the order z-, z+, y-, y+,
// x-, x+ (two triangles each).
std::shared_ptr<TriangleMesh> sharedCornerCube() {
  auto cube = std::make_shared<TriangleMesh>();
  for (int i = 0; i < 8; ++i) cube->positions.emplace_back(i & 1 ? 0.6f : -0.6f, i & 2 ? 0.6f : -0.6f, i & 4 ? 0.6f : -0.6f);
  const unsigned quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    cube->triangles.emplace_back(q[0], q[1], q[2]);
    cube->triangles.emplace_back(q[0], q[2], q[3]);
  }
  cube->computeNormals();
  return cube;
}

vtkActor* actorOfInstance(vtkRenderer* renderer, std::uint32_t id) {
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor())
    if (propInstanceId(a) == id) return a;
  return nullptr;
}

// The sphere-plane scene with its sphere replaced by sharedCornerCube(), in a 240 x 180 view.
struct CubeOverFloor {
  Scene scene = makeBuiltinScene("sphere-plane");
  std::shared_ptr<TriangleMesh> cube = sharedCornerCube();
  std::string replaced;  // the name of what the cube replaced
  std::unique_ptr<SceneView> view;
  SurfaceSamples surfaces;
  vtkActor* actor = nullptr;
  CubeOverFloor() {
    const auto placed = collectInstances(*scene.root);
    replaced = placed[1].geometry->name();
    placed[1].geometry->setMesh(cube);
    view = std::make_unique<SceneView>(scene, 240, 180);
    surfaces = captureSurfaces(view->window, view->renderer);
    actor = actorOfInstance(view->window.renderer(), placed[1].id);
  }
};

}  // namespace

TEST(BakedAO, ReachesTheFrameInterpolatedAndClearsAgain) {
  Scene scene = makeBuiltinScene("sphere-plane");
  SceneView view(scene, 200, 150);
  const SurfaceSamples surfaces = captureSurfaces(view.window, view.renderer);
  const auto instances = collectInstances(*scene.root);
  ASSERT_EQ(instances[0].geometry->name(), "floor");
  vtkActor* floor = actorOfInstance(view.window.renderer(), instances[0].id);
  ASSERT_NE(floor, nullptr);

  // A ramp in x over the floor: linear across every triangle, so interpolation reproduces it.
  const TriangleMesh& mesh = *instances[0].geometry->mesh();
  std::vector<float> ramp;
  for (const auto& p : mesh.positions) ramp.push_back((p.x + 4.0f) / 8.0f);
  setBakedAO(floor, ramp);
  EXPECT_TRUE(hasBakedAO(floor));
  EXPECT_THROW(setBakedAO(floor, {0.5f}), std::invalid_argument);

  vtkNew<BakedOnlyPass> pass;
  view.window.renderer()->SetPass(pass);
  view.window.render();
  std::vector<float> ao;
  ASSERT_TRUE(pass->ReadAO(vtkOpenGLRenderWindow::SafeDownCast(view.window.window()), ao));
  std::size_t floorPixels = 0, spherePixels = 0;
  double worstFloor = 0.0, worstSphere = 0.0;
  for (std::size_t i = 0; i < ao.size(); ++i) {
    if (!surfaces.covered[i]) continue;
    if (surfaces.position[i].z < 1e-3f) {
      ++floorPixels;
      worstFloor = std::max(worstFloor, std::abs(ao[i] - (surfaces.position[i].x + 4.0) / 8.0));
    } else {
      ++spherePixels;
      worstSphere = std::max(worstSphere, static_cast<double>(std::abs(ao[i])));
    }
  }
  EXPECT_GT(floorPixels, 5000u);
  EXPECT_GT(spherePixels, 1000u);
  EXPECT_LT(worstFloor, 2e-3) << "R16F holds the ramp to about 1e-3";
  EXPECT_EQ(worstSphere, 0.0) << "an actor without baked AO reads 0";

  clearBakedAO(floor);
  EXPECT_FALSE(hasBakedAO(floor));
  view.window.render();
  ASSERT_TRUE(pass->ReadAO(vtkOpenGLRenderWindow::SafeDownCast(view.window.window()), ao));
  double worst = 0.0;
  for (std::size_t i = 0; i < ao.size(); ++i)
    if (surfaces.covered[i]) worst = std::max(worst, static_cast<double>(std::abs(ao[i])));
  EXPECT_EQ(worst, 0.0);
  view.window.renderer()->SetPass(nullptr);
  pass->ReleaseGraphicsResources(view.window.window());
}

// Two values a point (front, then back): the G-buffer takes the side the eye sees, the side of
// the point's normal from above the floor, the other side from below it.
TEST(BakedAO, TwoSidedValuesFollowTheSideSeen) {
  Scene scene = makeBuiltinScene("sphere-plane");
  SceneView view(scene, 200, 150);
  const auto instances = collectInstances(*scene.root);
  ASSERT_EQ(instances[0].geometry->name(), "floor");
  vtkActor* floor = actorOfInstance(view.window.renderer(), instances[0].id);
  ASSERT_NE(floor, nullptr);
  const std::size_t n = instances[0].geometry->mesh()->positions.size();
  std::vector<float> sides(n, 0.2f);
  sides.resize(2 * n, 0.7f);
  setBakedAO(floor, sides);
  EXPECT_THROW(setBakedAO(floor, std::vector<float>(2 * n + 1, 0.0f)), std::invalid_argument);

  vtkNew<BakedOnlyPass> pass;
  view.window.renderer()->SetPass(pass);
  auto floorValues = [&](double cameraZ, std::size_t& pixels) {
    vtkCamera* camera = view.window.renderer()->GetActiveCamera();
    camera->SetPosition(0.0, -6.5, cameraZ);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 0.0, 1.0);
    view.window.renderer()->ResetCameraClippingRange();
    const SurfaceSamples surfaces = captureSurfaces(view.window, view.renderer);
    view.window.render();
    std::vector<float> ao;
    EXPECT_TRUE(pass->ReadAO(vtkOpenGLRenderWindow::SafeDownCast(view.window.window()), ao));
    double lo = 1.0, hi = 0.0;
    pixels = 0;
    for (std::size_t i = 0; i < ao.size(); ++i) {
      if (!surfaces.covered[i] || std::abs(surfaces.position[i].z) > 1e-3f) continue;
      ++pixels;
      lo = std::min(lo, static_cast<double>(ao[i]));
      hi = std::max(hi, static_cast<double>(ao[i]));
    }
    return std::make_pair(lo, hi);
  };
  std::size_t above = 0, below = 0;
  const auto front = floorValues(4.0, above), back = floorValues(-4.0, below);
  EXPECT_GT(above, 5000u);
  EXPECT_GT(below, 5000u);
  EXPECT_NEAR(front.first, 0.2, 1e-3);
  EXPECT_NEAR(front.second, 0.2, 1e-3);
  EXPECT_NEAR(back.first, 0.7, 1e-3);
  EXPECT_NEAR(back.second, 0.7, 1e-3);
  view.window.renderer()->SetPass(nullptr);
  pass->ReleaseGraphicsResources(view.window.window());
}

// Values on a crease split (core/CreaseSplit.h): a cube whose eight corners are shared vertices,
// one value per face. Drawn on the split, each face reads its own value to its edges; on the
// shared corners it would blend the three faces' values. The actor's source stays the mesh's.
TEST(BakedAO, ValuesOnACreaseSplitStayOnTheirFaces) {
  CubeOverFloor c;
  ASSERT_EQ(c.replaced, "sphere");
  ASSERT_NE(c.actor, nullptr);
  vtkPolyData* source = bakedAOSource(c.actor);
  ASSERT_EQ(source->GetNumberOfPoints(), 8);

  const CreaseSplit split = splitAtCreases(*c.cube);
  ASSERT_EQ(split.pointCount(), 24u);
  // Faces in quads order: z-, z+, y-, y+, x-, x+.
  auto faceValue = [](int face) { return 0.1f + 0.15f * static_cast<float>(face); };
  std::vector<float> values(split.pointCount(), -1.0f);
  for (std::size_t f = 0; f < split.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) values[split.triangles[f][k]] = faceValue(static_cast<int>(f / 2));
  setBakedAO(c.actor, values, split);
  EXPECT_TRUE(hasBakedAO(c.actor));
  EXPECT_EQ(bakedAOSource(c.actor), source);
  auto* drawn = vtkPolyData::SafeDownCast(c.actor->GetMapper()->GetInputDataObject(0, 0));
  ASSERT_NE(drawn, nullptr);
  EXPECT_EQ(drawn->GetNumberOfPoints(), 24);
  EXPECT_EQ(drawn->GetNumberOfCells(), source->GetNumberOfCells());
  // A split of other triangles is refused and leaves the values as they were.
  TriangleMesh turned = *c.cube;
  for (auto& t : turned.triangles) t = glm::uvec3(t.y, t.z, t.x);
  EXPECT_THROW(setBakedAO(c.actor, values, splitAtCreases(turned)), std::invalid_argument);
  EXPECT_EQ(vtkPolyData::SafeDownCast(c.actor->GetMapper()->GetInputDataObject(0, 0)), drawn);

  vtkNew<BakedOnlyPass> pass;
  c.view->window.renderer()->SetPass(pass);
  c.view->window.render();
  std::vector<float> ao;
  ASSERT_TRUE(pass->ReadAO(vtkOpenGLRenderWindow::SafeDownCast(c.view->window.window()), ao));
  std::size_t pixels = 0;
  double worst = 0.0;
  std::set<int> facesSeen;
  for (std::size_t i = 0; i < ao.size(); ++i) {
    if (!c.surfaces.covered[i] || c.surfaces.position[i].z < 1e-3f) continue;
    const glm::vec3 rel = c.surfaces.position[i] - glm::vec3(0.0f, 0.0f, 1.2f);
    const glm::vec3 a = glm::abs(rel);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    glm::vec3 others = a;
    others[axis] = 0.0f;
    if (a[axis] - std::max({others.x, others.y, others.z}) < 0.02f) continue;  // an edge's pixel
    const int face = 2 * (2 - axis) + (rel[axis] > 0.0f ? 1 : 0);
    facesSeen.insert(face);
    ++pixels;
    worst = std::max(worst, static_cast<double>(std::abs(ao[i] - faceValue(face))));
  }
  EXPECT_GT(pixels, 2000u);
  EXPECT_GE(facesSeen.size(), 2u);
  EXPECT_LT(worst, 2e-3) << "each face its own value, to its edges";

  clearBakedAO(c.actor);
  EXPECT_EQ(vtkPolyData::SafeDownCast(c.actor->GetMapper()->GetInputDataObject(0, 0)), source);
  c.view->window.renderer()->SetPass(nullptr);
  pass->ReleaseGraphicsResources(c.view->window.window());
}

// Values on a refined split (core/BakeRefinement.h): the same cube, its values a curve across x,
// v = 0.8 u^2 with u = (x + 0.6) / 1.2, which its corners (0 or 0.8) can only draw as a ramp (off by
// 0.2 at the middle). Refined twice where the values step, with each new point given the curve's
// value, the drawn copy follows the curve within what straight pieces a quarter apart can (0.8 / 64),
// and covers every pixel the mesh covers: no cracks where triangles were halved.
TEST(BakedAO, ValuesOnARefinedSplitFollowTheirPoints) {
  CubeOverFloor c;
  ASSERT_EQ(c.replaced, "sphere");
  ASSERT_NE(c.actor, nullptr);
  auto curve = [](float x) { const float u = (x + 0.6f) / 1.2f; return 0.8f * u * u; };
  CreaseSplit split = splitAtCreases(*c.cube);
  std::vector<float> values;
  auto valueOf = [&](int, std::uint32_t p) { return values[p]; };
  for (int round = 0; round < 2; ++round) {
    values.resize(split.pointCount());
    for (std::size_t p = 0; p < split.pointCount(); ++p) values[p] = curve(split.position(*c.cube, p).x);
    ASSERT_GT(refineWhereValuesStep(split, *c.cube, valueOf, 1, 0.03f, 0.0), 0u);
  }
  values.resize(split.pointCount());
  for (std::size_t p = 0; p < split.pointCount(); ++p) values[p] = curve(split.position(*c.cube, p).x);
  setBakedAO(c.actor, values, split);
  auto* drawn = vtkPolyData::SafeDownCast(c.actor->GetMapper()->GetInputDataObject(0, 0));
  ASSERT_NE(drawn, nullptr);
  EXPECT_EQ(drawn->GetNumberOfPoints(), static_cast<vtkIdType>(split.pointCount()));
  EXPECT_EQ(drawn->GetNumberOfPolys(), static_cast<vtkIdType>(split.triangles.size()));

  vtkNew<BakedOnlyPass> pass;
  c.view->window.renderer()->SetPass(pass);
  c.view->window.render();
  std::vector<float> ao;
  std::vector<std::uint8_t> covered;
  ASSERT_TRUE(pass->ReadAO(vtkOpenGLRenderWindow::SafeDownCast(c.view->window.window()), ao, &covered));
  std::size_t pixels = 0, cracks = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < ao.size(); ++i) {
    if (c.surfaces.covered[i] && !covered[i]) ++cracks;
    if (!c.surfaces.covered[i] || c.surfaces.position[i].z < 1e-3f) continue;  // the cube, not the floor
    ++pixels;
    worst = std::max(worst, static_cast<double>(std::abs(ao[i] - curve(c.surfaces.position[i].x))));
  }
  EXPECT_GT(pixels, 2000u);
  EXPECT_EQ(cracks, 0u);
  EXPECT_LT(worst, 0.8 / 64 + 2e-3) << "the curve between points a quarter apart";
  c.view->window.renderer()->SetPass(nullptr);
  pass->ReleaseGraphicsResources(c.view->window.window());
}
