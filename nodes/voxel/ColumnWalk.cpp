#include "voxel/ColumnWalk.h"

#include <algorithm>
#include <cmath>

#include "core/Finite.h"

namespace aokit {

int columnWalkBound(double lengthVoxels) {
  const double n = std::ceil(std::sqrt(2.0) * std::max(0.0, lengthVoxels)) + 4.0;
  return static_cast<int>(std::min(n, 1e6));
}

namespace {
// [t0, t1] narrowed to where o + t dir is inside [0, dims] per axis; false if nothing is left.
bool clipToBox(const glm::vec3& o, const glm::vec3& dir, const glm::ivec3& dims, float& t0, float& t1) {
  for (int a = 0; a < 3; ++a) {
    const float hi = static_cast<float>(dims[a]);
    if (dir[a] == 0.0f) {
      if (!(o[a] >= 0.0f && o[a] <= hi)) return false;
      continue;
    }
    const float ta = (0.0f - o[a]) / dir[a], tb = (hi - o[a]) / dir[a];
    t0 = std::max(t0, std::min(ta, tb));
    t1 = std::min(t1, std::max(ta, tb));
  }
  return t0 <= t1;
}
}  // namespace

bool columnWalk(const VoxelGrid& grid, const glm::vec3& o, const glm::vec3& dir, float t0, float t1, int maxColumns,
                float& tHit) {
  if (!allFinite(o) || !allFinite(dir) || !std::isfinite(t0) || !std::isfinite(t1)) return false;
  if (!(t0 <= t1) || !clipToBox(o, dir, grid.dims(), t0, t1)) return false;
  const glm::vec2 start = glm::vec2(o) + t0 * glm::vec2(dir);
  glm::ivec2 c(glm::floor(start));
  const glm::ivec2 stepC(dir.x >= 0.0f ? 1 : -1, dir.y >= 0.0f ? 1 : -1);
  // t from one x (y) boundary to the next; a huge finite value for an axis the ray does not move on.
  const glm::vec2 delta = 1.0f / glm::max(glm::abs(glm::vec2(dir)), glm::vec2(1e-20f));
  const glm::vec2 f = start - glm::vec2(c);
  glm::vec2 next = t0 + glm::vec2(dir.x >= 0.0f ? 1.0f - f.x : f.x, dir.y >= 0.0f ? 1.0f - f.y : f.y) * delta;
  float t = t0, tn = t0;
  int k0 = 0, k1 = 0;
  bool hit = false;
  for (int n = 0; n < maxColumns; ++n) {
    tn = std::min(std::min(next.x, next.y), t1);
    const float za = o.z + t * dir.z, zb = o.z + tn * dir.z;
    k0 = static_cast<int>(std::floor(std::min(za, zb)));
    k1 = static_cast<int>(std::floor(std::max(za, zb)));
    hit = grid.anyInRun(c.x, c.y, k0, k1);
    if (hit || !(tn < t1)) break;
    const bool xNext = next.x < next.y;
    t = xNext ? next.x : next.y;
    if (xNext) {
      c.x += stepC.x;
      next.x += delta.x;
    } else {
      c.y += stepC.y;
      next.y += delta.y;
    }
  }
  if (!hit) return false;
  // The first set voxel along the ray, and where the ray enters its depth slab.
  const bool up = dir.z >= 0.0f;
  k0 = std::max(k0, 0);
  k1 = std::min(k1, grid.dims().z - 1);
  int k = up ? k0 : k1;
  while (!grid.get(c.x, c.y, k)) k += up ? 1 : -1;
  const float plane = static_cast<float>(up ? k : k + 1);
  const float entry = dir.z != 0.0f ? (plane - o.z) / dir.z : t;
  tHit = std::clamp(entry, t, tn);
  return true;
}

}  // namespace aokit
