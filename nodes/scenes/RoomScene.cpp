// "room" / "room-dark": a closed room with thin walls and furniture, camera inside. Thin walls
// (0.04 against R = 0.5) stress field resolution and voxel sizes; the closed room lets light
// bounce, which the ambient-transfer tests compare between light and dark albedo.
#include "scenes/SceneBuilders.h"
#include "scenes/SceneBuilding.h"
#include "scenes/Shapes.h"

namespace aokit {
namespace {

// An axis-aligned box given by its min and max corners.
void addSlab(Group& parent, const glm::dvec3& lo, const glm::dvec3& hi, const glm::vec3& albedo,
             const std::string& name) {
  addPlaced(parent, makeBox(hi - lo), translation(0.5 * (lo + hi)), albedo, name);
}

}  // namespace

Scene makeRoomScene(float albedo) {
  Scene scene;
  const glm::vec3 a(albedo);
  Group& root = *scene.root;
  // Interior: x, y in [-2, 2], z in [0, 2.5]; every wall 0.04 thick, outside the interior.
  const double w = 0.04, h = 2.5;
  addSlab(root, {-2 - w, -2 - w, -w}, {2 + w, 2 + w, 0}, a, "floor");
  addSlab(root, {-2 - w, -2 - w, h}, {2 + w, 2 + w, h + w}, a, "ceiling");
  addSlab(root, {-2 - w, -2, 0}, {-2, 2, h}, a, "wall -x");
  addSlab(root, {2, -2, 0}, {2 + w, 2, h}, a, "wall +x");
  addSlab(root, {-2 - w, -2 - w, 0}, {2 + w, -2, h}, a, "wall -y");
  addSlab(root, {-2 - w, 2, 0}, {2 + w, 2 + w, h}, a, "wall +y");

  // Table: 1.4 x 0.8 top at height 0.75 on four thin legs.
  const glm::dvec2 tc(-0.3, 0.3);
  addSlab(root, {tc.x - 0.7, tc.y - 0.4, 0.71}, {tc.x + 0.7, tc.y + 0.4, 0.75}, a, "table top");
  for (int sx = -1; sx <= 1; sx += 2)
    for (int sy = -1; sy <= 1; sy += 2) {
      const glm::dvec2 c = tc + glm::dvec2(sx * 0.62, sy * 0.32);
      addSlab(root, {c.x - 0.025, c.y - 0.025, 0}, {c.x + 0.025, c.y + 0.025, 0.71}, a, "table leg");
    }

  // Shelves against the -x wall: two side panels and four boards, 2 cm boards, 1 cm off the wall.
  const double x0 = -1.99, x1 = -1.64, y0 = 0.6, y1 = 1.8;
  addSlab(root, {x0, y0, 0}, {x1, y0 + 0.02, 1.8}, a, "shelf side");
  addSlab(root, {x0, y1 - 0.02, 0}, {x1, y1, 1.8}, a, "shelf side");
  for (double z : {0.05, 0.6, 1.2, 1.78})
    addSlab(root, {x0, y0 + 0.02, z}, {x1, y1 - 0.02, z + 0.02}, a, "shelf board");

  // A crate in the far corner and a low cabinet by the +y wall.
  addSlab(root, {1.1, 1.2, 0}, {1.6, 1.7, 0.5}, a, "crate");
  addSlab(root, {-0.4, 1.5, 0}, {0.6, 1.98, 0.9}, a, "cabinet");

  scene.camera.position = {1.7, -1.7, 1.6};
  scene.camera.focalPoint = {-0.6, 0.6, 0.6};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 60.0;  // wide, as inside a room
  scene.root->setAORadius(0.5);
  return scene;
}

}  // namespace aokit
