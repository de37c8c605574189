// "cubes": unit cubes scattered on a floor, seeded. Many small occluders with contact creases: the
// case where per-object fields and voxel grids pay per occluder.
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "scenes/SceneBuilders.h"
#include "scenes/SceneBuilding.h"
#include "scenes/SeededRandom.h"
#include "scenes/Shapes.h"

namespace aokit {

Scene makeCubesScene(int count, std::uint32_t seed) {
  if (count < 1 || count > 100)
    throw std::invalid_argument("cubes: cube count " + std::to_string(count) + " is outside 1..100");
  SeededRandom rng(seed);

  // Layout: a k x k grid of cells, `count` distinct cells picked at random, one cube per cell with
  // a jitter small enough that a cube at any rotation (circumradius sqrt(0.5)) stays inside its
  // cell. Non-overlap is thus guaranteed without rejection sampling.
  const double cell = 1.8;
  const double jitter = 0.5 * cell - std::sqrt(0.5) - 0.02;
  const int k = static_cast<int>(std::ceil(std::sqrt(1.5 * count)));
  std::vector<int> cells(static_cast<std::size_t>(k * k));
  std::iota(cells.begin(), cells.end(), 0);
  for (int i = 0; i < count; ++i) std::swap(cells[i], cells[i + rng.index(k * k - i)]);  // partial Fisher-Yates

  Scene scene;
  const double half = 0.5 * k * cell;
  const double floorHalf = half + 1.5;
  addPlaced(*scene.root, makeGridPlane(2 * floorHalf, 2 * floorHalf, 16, 16), glm::dmat4(1.0),
            glm::vec3(kDefaultAlbedo), "floor");
  auto cube = makeBox(glm::dvec3(1.0));
  for (int i = 0; i < count; ++i) {
    const int cx = cells[i] % k, cy = cells[i] / k;
    const glm::dvec3 centre(-half + (cx + 0.5) * cell + rng.uniform(-jitter, jitter),
                            -half + (cy + 0.5) * cell + rng.uniform(-jitter, jitter), 0.5);
    const double angle = rng.uniform(0.0, 360.0);
    addPlaced(*scene.root, cube, translation(centre) * rotation(angle, {0, 0, 1}), glm::vec3(kDefaultAlbedo),
              "cube" + std::to_string(i));
  }

  // Looking down at 35 degrees from the -y side, far enough to see the whole layout.
  const double elevation = glm::radians(35.0), distance = 2.6 * floorHalf;
  scene.camera.focalPoint = {0.0, 0.0, 0.0};
  scene.camera.position = {0.0, -distance * std::cos(elevation), distance * std::sin(elevation)};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 30.0;
  scene.root->setAORadius(1.0);
  return scene;
}

}  // namespace aokit
