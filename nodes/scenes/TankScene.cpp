// "tank": a vehicle of boxes and cylinders on a floor. Mid-sized occluders with narrow gaps (wheels
// under fenders, turret on hull): the everyday case for field and voxel methods.
#include "scenes/SceneBuilders.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

namespace aokit {
namespace {

// Cylinders are built along +z from z = 0; these turn that axis.
glm::dmat4 zToX() { return rotation(90.0, {0, 1, 0}); }
glm::dmat4 zToY() { return rotation(-90.0, {1, 0, 0}); }

}  // namespace

Scene makeTankScene() {
  Scene scene;
  const glm::vec3 grey(kDefaultAlbedo);
  Group& root = *scene.root;
  addPlaced(root, makeGridPlane(30.0, 30.0, 16, 16), glm::dmat4(1.0), grey, "floor");

  // The vehicle points along +x; its hull is 6.4 long, so the whole tank is about 8 with the barrel.
  auto vehicle = std::make_shared<Transform>();
  vehicle->setName("tank");
  vehicle->setMatrix(rotation(20.0, {0, 0, 1}));
  root.addChild(vehicle);

  addPlaced(*vehicle, makeBox({5.6, 2.2, 0.6}), translation({0, 0, 0.8}), grey, "lower hull");
  addPlaced(*vehicle, makeBox({6.4, 3.4, 0.6}), translation({0, 0, 1.4}), grey, "upper hull");
  addPlaced(*vehicle, makeBox({2.8, 2.2, 0.8}), translation({-0.4, 0, 2.1}), grey, "turret");
  addPlaced(*vehicle, makeCylinder(0.12, 3.6, 24), translation({1.0, 0, 2.15}) * zToX(), grey, "barrel");

  // Five road wheels a side, radius 0.45, touching the floor, tucked under the upper hull.
  auto wheel = makeCylinder(0.45, 0.4, 32);
  for (int side = -1; side <= 1; side += 2) {
    for (int i = 0; i < 5; ++i) {
      const double x = -2.4 + 1.2 * i;
      const double y = side * 1.35 - 0.2;  // the wheel spans y .. y + 0.4, clear of the lower hull
      addPlaced(*vehicle, wheel, translation({x, y, 0.45}) * zToY(), grey, "wheel");
    }
  }

  scene.camera.position = {9.0, -11.0, 6.5};
  scene.camera.focalPoint = {0.0, 0.0, 1.0};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 30.0;
  scene.root->setAORadius(2.0);  // about a quarter of the vehicle's length
  return scene;
}

}  // namespace aokit
