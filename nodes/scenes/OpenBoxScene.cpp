// open-box: a unit cube without its front face, standing on the sphere-plane floor and seen through
// the open side with the sphere-plane camera. Open surfaces, clipped data and single-sided sheets
// are everyday input in scientific viewers: inside the box the eye sees the back sides of the walls,
// so every normal there must be turned toward the eye (the G-buffer and the reference alike).
#include "scenes/SceneBuilders.h"

#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

namespace aokit {

Scene makeOpenBoxScene() {
  Scene scene;
  addPlaced(*scene.root, makeGridPlane(8.0, 8.0, 64, 64), glm::dmat4(1.0), glm::vec3(1.0f), "floor");
  // Five unit faces, each a plane (normal +z) turned so that its normal points out of the box.
  const auto face = makeGridPlane(1.0, 1.0, 1, 1);
  const glm::vec3 white(1.0f);
  addPlaced(*scene.root, face, rotation(180.0, {1, 0, 0}), white, "bottom");
  addPlaced(*scene.root, face, translation({0.0, 0.0, 1.0}), white, "top");
  addPlaced(*scene.root, face, translation({0.0, 0.5, 0.5}) * rotation(-90.0, {1, 0, 0}), white, "back");
  addPlaced(*scene.root, face, translation({-0.5, 0.0, 0.5}) * rotation(-90.0, {0, 1, 0}), white, "left");
  addPlaced(*scene.root, face, translation({0.5, 0.0, 0.5}) * rotation(90.0, {0, 1, 0}), white, "right");
  scene.root->setAORadius(1.5);
  scene.root->setFalloff(Falloff::Binary);
  scene.camera.position = {0.0, -6.5, 4.0};
  scene.camera.focalPoint = {0.0, 0.0, 0.7};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 30.0;
  return scene;
}

}  // namespace aokit
