// "stack": boxes standing close together, one lying across two others. Seen from the floor between
// them and from their facing sides, several occluders cover overlapping parts of the hemisphere:
// the case where multiplying per-occluder shadows over-darkens and merging cones (seed 001) helps.
#include "scenes/SceneBuilders.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

namespace aokit {

namespace {
struct StackBox {
  const char* name;
  glm::dvec3 size, centre;
};
// Gaps of 0.3 between neighbours, well inside R = 1.
const StackBox kBoxes[] = {
    {"left pillar", {1.0, 1.0, 1.4}, {-0.65, 0.0, 0.7}},
    {"right pillar", {1.0, 1.0, 1.4}, {0.65, 0.0, 0.7}},
    {"plank", {2.6, 1.0, 0.4}, {0.0, 0.0, 1.6}},        // lies across both pillars
    {"back left", {1.0, 1.0, 2.2}, {-0.65, 1.3, 1.1}},
    {"back right", {1.0, 1.0, 1.6}, {0.65, 1.3, 0.8}},
    {"front cube", {0.8, 0.8, 0.8}, {0.0, -1.2, 0.4}},
};
}  // namespace

Scene makeStackScene() {
  Scene scene;
  const glm::vec3 grey(kDefaultAlbedo);
  addPlaced(*scene.root, makeGridPlane(12.0, 12.0, 16, 16), glm::dmat4(1.0), grey, "floor");
  for (const StackBox& b : kBoxes) addPlaced(*scene.root, makeBox(b.size), translation(b.centre), grey, b.name);

  scene.camera.position = {3.5, -7.0, 5.0};
  scene.camera.focalPoint = {0.0, 0.3, 0.8};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 30.0;
  scene.root->setAORadius(1.0);
  return scene;
}

}  // namespace aokit
