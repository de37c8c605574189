// "corridor": a door panel standing far (8 R) in front of the corridor's back wall, seen down the
// corridor so that its silhouette overlaps the back wall on screen. Screen-space AO sees a large
// depth step there and darkens the wall around the door: a false occlusion that the reference does
// not have.
#include "scenes/SceneBuilders.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

namespace aokit {

Scene makeCorridorScene() {
  Scene scene;
  const glm::vec3 grey(kDefaultAlbedo);
  Group& root = *scene.root;
  // The corridor runs along +y from y = 0 to y = 16; 2.5 wide (x in [-1.25, 1.25]), 2.5 high, open top.
  const double width = 2.5, length = 16.0, height = 2.5, wall = 0.1;
  addPlaced(root, makeGridPlane(width, length, 4, 32), translation({0, 0.5 * length, 0}), grey, "floor");
  for (int side = -1; side <= 1; side += 2)
    addPlaced(root, makeBox({wall, length, height}),
              translation({side * 0.5 * (width + wall), 0.5 * length, 0.5 * height}), grey,
              side < 0 ? "left wall" : "right wall");
  addPlaced(root, makeBox({width + 2 * wall, wall, height}), translation({0, length + 0.5 * wall, 0.5 * height}),
            grey, "back wall");
  // The door: 1 x 2, 4 units (8 R) in front of the back wall, a little off centre.
  addPlaced(root, makeBox({1.0, 0.05, 2.0}), translation({0.2, length - 4.0, 1.0}), grey, "door");

  scene.camera.position = {0.0, 0.5, 1.6};
  scene.camera.focalPoint = {0.0, length, 1.1};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 30.0;
  scene.root->setAORadius(0.5);
  return scene;
}

}  // namespace aokit
