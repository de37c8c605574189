// "behind": a pillar against a wall just behind the camera (negative view depth), while the wall
// ahead of the camera is in view: the pillar's AO on the visible wall (and floor) comes from
// behind the image plane, where no screen-space method and no guard band can see it.
#include "scenes/SceneBuilders.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

namespace aokit {
namespace {

void addBlock(Group& parent, const glm::dvec3& lo, const glm::dvec3& hi, const std::string& name) {
  addPlaced(parent, makeBox(hi - lo), translation(0.5 * (lo + hi)), glm::vec3(kDefaultAlbedo), name);
}

}  // namespace

Scene makeBehindScene() {
  Scene scene;
  Group& root = *scene.root;
  // A floor x in [-1, 5], y in [-3, 9], the wall along its -x side and a far wall at y = 9.
  addPlaced(root, makeGridPlane(6.0, 12.0, 12, 24), translation({2.0, 3.0, 0.0}), glm::vec3(kDefaultAlbedo),
            "floor");
  addBlock(root, {-1.1, -3.0, 0.0}, {-1.0, 9.0, 3.0}, "wall");
  addBlock(root, {-1.1, 9.0, 0.0}, {5.0, 9.1, 3.0}, "far wall");
  // Behind the camera plane y = 0 (the view is horizontal, along +y).
  addBlock(root, {-1.0, -0.9, 0.0}, {-0.3, -0.05, 2.4}, "pillar behind");

  scene.camera.position = {-0.75, 0.0, 1.3};
  scene.camera.focalPoint = {-0.75, 5.0, 1.3};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 60.0;
  scene.root->setAORadius(1.0);
  return scene;
}

}  // namespace aokit
