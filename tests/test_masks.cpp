// Node masks reach every stage alike: a prop that does not receive AO gets 0 in the reference and
// in the deferred pipeline's output; a prop that does not cast is no occluder for the reference and
// is open to screen-space containment tests.
#include <gtest/gtest.h>

#include "core/Geometry.h"
#include "core/NodeVisitor.h"
#include "headless/FrameCapture.h"
#include "headless/SceneView.h"
#include "methods/MethodRegistry.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "scenes/BuiltinScenes.h"

using namespace aokit;

namespace {

struct Result {
  double referenceFloor = 0, methodFloor = 0, referenceSphere = 0, methodSphere = 0;
};

// Mean AO on floor and sphere pixels of sphere-plane, reference and obscurance, with the given
// masks on the floor's and the sphere's transforms.
Result run(std::uint32_t floorMask, std::uint32_t sphereMask) {
  Scene scene = makeBuiltinScene("sphere-plane");
  const auto instances = collectInstances(*scene.root);
  // addPlaced puts each Geometry under its own Transform: mask the Geometry itself.
  instances[0].geometry->setMask(floorMask);
  instances[1].geometry->setMask(sphereMask);
  SceneView view(scene, 192, 144);
  const SurfaceSamples surfaces = captureSurfaces(view.window, view.renderer);
  EmbreeScene embree(*scene.root);
  const AOBuffer ref = computeReferenceAO(embree, surfaces, sceneReferenceOptions(*scene.root, 64, 3));
  scene.root->setTechnique(makeTechnique("obscurance", "samples=8"));
  view.renderer.sync();
  const AOBuffer ao = captureAO(view.window, view.renderer, surfaces.covered);
  Result r;
  std::size_t floorN = 0, sphereN = 0;
  for (std::size_t i = 0; i < surfaces.pixelCount(); ++i) {
    if (!surfaces.covered[i]) continue;
    const bool floor = surfaces.position[i].z < 1e-3f;
    (floor ? r.referenceFloor : r.referenceSphere) += ref.ao[i];
    (floor ? r.methodFloor : r.methodSphere) += ao.ao[i];
    ++(floor ? floorN : sphereN);
  }
  r.referenceFloor /= floorN;
  r.methodFloor /= floorN;
  r.referenceSphere /= sphereN;
  r.methodSphere /= sphereN;
  return r;
}

}  // namespace

TEST(Masks, AFloorThatReceivesNoAOGetsZeroEverywhere) {
  const Result all = run(kDefaultMask, kDefaultMask);
  ASSERT_GT(all.referenceFloor, 0.01);
  ASSERT_GT(all.methodFloor, 0.01);
  const Result r = run(kCastsAO | kVisible, kDefaultMask);
  EXPECT_EQ(r.referenceFloor, 0.0);
  EXPECT_EQ(r.methodFloor, 0.0);
  EXPECT_NEAR(r.referenceSphere, all.referenceSphere, 1e-9) << "the floor still casts onto the sphere";
  EXPECT_GT(r.methodSphere, 0.5 * all.methodSphere);
}

TEST(Masks, ASphereThatCastsNoAOLeavesTheFloorOpen) {
  const Result all = run(kDefaultMask, kDefaultMask);
  const Result r = run(kDefaultMask, kReceivesAO | kVisible);
  // The floor is flat: only the sphere occludes it.
  EXPECT_LT(r.referenceFloor, 1e-4);
  EXPECT_LT(r.methodFloor, 0.2 * all.methodFloor) << "screen space must not count the sphere's pixels";
  EXPECT_GT(r.referenceSphere, 0.01) << "the sphere still receives from the floor";
}
