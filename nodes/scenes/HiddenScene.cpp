// "hidden": an occluder standing right in front of a back wall, hidden from the camera by a panel
// nearer the camera (the seed's Figure 9, left). The panel covers the occluder's whole silhouette,
// but the occluder's AO reaches the wall and floor around the panel's silhouette, which are in
// view: a screen-space method cannot see what casts it. The panel is 1.4 (1.4 R) in front of the
// wall, so it casts nothing there itself.
#include "scenes/SceneBuilders.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

namespace aokit {
namespace {

void addBlock(Group& parent, const glm::dvec3& lo, const glm::dvec3& hi, const std::string& name) {
  addPlaced(parent, makeBox(hi - lo), translation(0.5 * (lo + hi)), glm::vec3(kDefaultAlbedo), name);
}

}  // namespace

Scene makeHiddenScene() {
  Scene scene;
  Group& root = *scene.root;
  addPlaced(root, makeGridPlane(10.0, 10.0, 20, 20), translation({0.0, 1.0, 0.0}), glm::vec3(kDefaultAlbedo),
            "floor");
  addBlock(root, {-4.0, 3.0, 0.0}, {4.0, 3.1, 3.0}, "back wall");
  // 0.1 in front of the wall: seen from the camera it lies wholly behind the panel.
  addBlock(root, {-0.4, 2.5, 0.0}, {0.4, 2.9, 1.6}, "hidden occluder");
  addBlock(root, {-0.4, 1.5, 0.0}, {0.4, 1.6, 2.0}, "front panel");

  scene.camera.position = {0.0, -4.0, 1.2};
  scene.camera.focalPoint = {0.0, 3.0, 1.0};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 30.0;
  scene.root->setAORadius(1.0);
  return scene;
}

}  // namespace aokit
