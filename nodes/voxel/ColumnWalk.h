#pragma once
// The segment test's walk (HybridSettings::segmentTest): a ray through the bit-packed grid one
// (x, y) column at a time, each column tested over the depth the ray spends in it. One texel of
// the packed grid holds 32 voxels of a column's depth, so a column is one fetch for most rays, and
// the walk is exact: it meets every voxel the ray passes, and no other, whatever the step length
// (a march of point samples steps past a sheet between two of them). The GPU's haoColumnWalk
// (shaders/HybridMarchFS.glsl) walks the same columns, finding the first set voxel a word at a
// time where this looks voxel by voxel.
#include <glm/glm.hpp>

#include "voxel/VoxelGrid.h"

namespace aokit {

// Columns a ray of `lengthVoxels` (grid units, >= 0) can pass, with margin: the walk's iteration
// bound (|dx| + |dy| <= sqrt 2 of the length, each axis's boundaries at most |d| + 1, plus the
// first column and round-off).
int columnWalkBound(double lengthVoxels);

// The ray o + t dir (grid units), t0 <= t <= t1 clipped to the grid's box [0, dims], at most
// maxColumns columns: true if it passes a set voxel, with tHit where it enters the first one
// (along the ray). Outside the grid reads as empty. t0 > t1, a non-finite input or an empty clip
// is a miss.
bool columnWalk(const VoxelGrid& grid, const glm::vec3& o, const glm::vec3& dir, float t0, float t1, int maxColumns,
                float& tHit);

}  // namespace aokit
