// sphere-plane and sphere-offscreen, exactly as ../shared/notes/canonical-scenes.md defines them:
// published figures were measured on these, so geometry, cameras and radius must not drift.
#include "scenes/SceneBuilders.h"

#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

namespace aokit {
namespace {

// White: the note's AO-only comparisons use a white, ambient-only material.
constexpr float kWhite = 1.0f;

Scene makeSphereOverFloor(int slices = 256, int stacks = 128) {
  Scene scene;
  // Floor: z = 0, x, y in [-4, 4]. A 64 x 64 grid rather than two triangles so that per-vertex
  // consumers (bakers, debugging views) have samples; the surface is the same flat square.
  addPlaced(*scene.root, makeGridPlane(8.0, 8.0, 64, 64), glm::dmat4(1.0), glm::vec3(kWhite), "floor");
  addPlaced(*scene.root, makeUVSphere(1.0, slices, stacks), translation({0.0, 0.0, 1.2}), glm::vec3(kWhite), "sphere");
  scene.root->setAORadius(1.5);
  scene.root->setFalloff(Falloff::Binary);
  return scene;
}

}  // namespace

Scene makeSpherePlaneScene() { return makeSpherePlaneScene(256, 128); }

Scene makeSpherePlaneScene(int sphereSlices, int sphereStacks) {
  Scene scene = makeSphereOverFloor(sphereSlices, sphereStacks);
  scene.name = "sphere-plane";
  scene.camera.position = {0.0, -6.5, 4.0};
  scene.camera.focalPoint = {0.0, 0.0, 0.7};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 30.0;
  return scene;
}

Scene makeSphereOffscreenScene() {
  Scene scene = makeSphereOverFloor();
  scene.name = "sphere-offscreen";
  scene.camera.position = {0.0, -3.2, 3.0};
  scene.camera.focalPoint = {0.0, -2.2, 0.0};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 30.0;
  return scene;
}

}  // namespace aokit
