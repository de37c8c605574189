#include "voxel/VoxelFrame.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "voxel/HybridSampling.h"

namespace aokit {

glm::mat4 VoxelFrame::worldToGridMatrix() const {
  const glm::dmat3 r = glm::transpose(axes) / voxelSize;
  glm::dmat4 m(r);
  m[3] = glm::dvec4(-(r * origin), 1.0);
  return glm::mat4(m);
}

Bounds VoxelFrame::worldBounds() const {
  Bounds b;
  for (int c = 0; c < 8; ++c)
    b.extend(toWorld(glm::dvec3((c & 1) ? dims.x : 0, (c & 2) ? dims.y : 0, (c & 4) ? dims.z : 0)));
  return b;
}

namespace {

// The box in the frame's coordinates.
Bounds localBox(const Bounds& box, const glm::dmat3& axes, int resolution, int minResolution) {
  if (!box.valid() || !std::isfinite(box.diagonal()))
    throw std::invalid_argument("voxel frame: the region is empty or not finite");
  if (resolution < minResolution)
    throw std::invalid_argument("voxel frame: resolution must be >= " + std::to_string(minResolution));
  Bounds local;
  const glm::dmat3 toLocal = glm::transpose(axes);
  for (int c = 0; c < 8; ++c)
    local.extend(toLocal * glm::dvec3((c & 1) ? box.max.x : box.min.x, (c & 2) ? box.max.y : box.min.y,
                                      (c & 4) ? box.max.z : box.min.z));
  return local;
}

}  // namespace

VoxelFrame VoxelFrame::onLattice(const Bounds& box, int resolution, const glm::dmat3& axes) {
  const Bounds local = localBox(box, axes, resolution, 2);
  const glm::dvec3 side = local.max - local.min;
  const double longest = std::max({side.x, side.y, side.z});
  if (!(longest > 0.0)) throw std::invalid_argument("voxel frame: the region has no extent");
  VoxelFrame f;
  f.axes = axes;
  f.voxelSize = std::exp2(std::ceil(8.0 * std::log2(longest / (resolution - 2))) / 8.0);
  const glm::dvec3 lowLocal = (glm::floor(local.min / f.voxelSize - 0.5) + 0.5) * f.voxelSize;
  for (int a = 0; a < 3; ++a)
    f.dims[a] = std::clamp(static_cast<int>(std::ceil((local.max[a] - lowLocal[a]) / f.voxelSize)), 1, resolution);
  f.origin = axes * lowLocal;
  return f;
}

VoxelFrame VoxelFrame::fitting(const Bounds& box, int resolution, const glm::dmat3& axes) {
  const Bounds local = localBox(box, axes, resolution, 1);
  const glm::dvec3 side = local.max - local.min;
  const double longest = std::max({side.x, side.y, side.z});
  if (!(longest > 0.0)) throw std::invalid_argument("voxel frame: the region has no extent");
  VoxelFrame f;
  f.axes = axes;
  f.voxelSize = longest / resolution;
  for (int a = 0; a < 3; ++a)
    f.dims[a] = std::clamp(static_cast<int>(std::ceil(side[a] / f.voxelSize - 1e-9)), 1, resolution);
  const glm::dvec3 lowLocal = local.center() - 0.5 * f.voxelSize * glm::dvec3(f.dims);
  f.origin = axes * lowLocal;
  return f;
}

glm::dmat3 randomRotation(std::uint32_t seed) {
  // Shoemake's uniform random unit quaternion from three uniform numbers.
  const std::uint32_t h1 = hybridHash(seed ^ 0x9e3779b9u), h2 = hybridHash(h1), h3 = hybridHash(h2);
  const double u1 = hashToUnit(h1), u2 = hashToUnit(h2), u3 = hashToUnit(h3);
  const double twoPi = 6.283185307179586;
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  const double x = a * std::sin(twoPi * u2), y = a * std::cos(twoPi * u2);
  const double z = b * std::sin(twoPi * u3), w = b * std::cos(twoPi * u3);
  glm::dmat3 m;
  m[0] = {1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)};
  m[1] = {2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)};
  m[2] = {2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)};
  return m;
}

}  // namespace aokit
