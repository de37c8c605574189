#pragma once
// Where a voxel grid sits in the world: a corner, three orthonormal axes and a cubic voxel size.
// Grid coordinates g = A^T (p - origin) / voxelSize, so voxel (i, j, k) is the unit cube
// [i, i+1] x [j, j+1] x [k, k+1] in g; k runs along axes[2], the depth axis of VoxelGrid.h (the
// voxelizing camera's viewing direction for the seed's rasterization).
#include <cstdint>

#include <glm/glm.hpp>

#include "core/Bounds.h"

namespace aokit {

struct VoxelFrame {
  glm::dvec3 origin{0.0};  //!< world position of grid point (0, 0, 0)
  glm::dmat3 axes{1.0};    //!< columns: grid x, y, z in world; orthonormal, right-handed
  double voxelSize = 1.0;  //!< world units, > 0
  glm::ivec3 dims{1};      //!< voxels per axis

  glm::dvec3 toGrid(const glm::dvec3& p) const { return glm::transpose(axes) * (p - origin) / voxelSize; }
  glm::dvec3 toWorld(const glm::dvec3& g) const { return origin + axes * (g * voxelSize); }
  // The same map as a float matrix for a shader uniform (column-major, as glUniformMatrix4fv).
  glm::mat4 worldToGridMatrix() const;
  // World bounds of the whole grid (all eight corners).
  Bounds worldBounds() const;

  // The smallest grid with these axes that covers `box`: voxelSize = longest side (in the axes'
  // frame) / resolution, dims = ceil(side / voxelSize) >= 1, centred on the box. A rotated frame
  // covers a larger box than an axis-aligned one (up to sqrt(3) per side), so its voxels are larger.
  // Throws std::invalid_argument on an invalid or empty box or resolution < 1.
  static VoxelFrame fitting(const Bounds& box, int resolution, const glm::dmat3& axes = glm::dmat3(1.0));

  // As fitting(), but on a fixed lattice, so that regions that move or resize a little between
  // frames keep the same voxels (temporal stability): voxelSize is the smallest 2^(q/8) (q an
  // integer, world units) >= longest side / (resolution - 2), and the origin, in the axes' frame,
  // an odd multiple of half of it, so that surfaces at round coordinates (a floor at z = 0) lie
  // mid-voxel, not on a voxel boundary where the normal offset would sit on a rounding edge.
  // dims stay <= resolution; the price is up to 9% of the resolution per axis, plus 2 voxels.
  static VoxelFrame onLattice(const Bounds& box, int resolution, const glm::dmat3& axes = glm::dmat3(1.0));
};

// A uniformly distributed rotation (columns orthonormal, det +1) from a seed: the seed's randomly
// rotated voxelizing camera. Same seed, same rotation on every platform.
glm::dmat3 randomRotation(std::uint32_t seed);

}  // namespace aokit
