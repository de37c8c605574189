#pragma once
// resolution = auto: a field as fine as the occluder's size relative to R needs, no finer.
//
// Cube: a face spans pi/2, so a texel at the bounding radius rho covers about rho (pi/2) / N.
//   The cap model varies over distances of order R, so two texels per R there are enough:
//   rho (pi/2) / N <= R / 2, i.e. N = ceil(pi rho / R).
// Grid: the seed's normal offset is one cell and its blur spreads the voxelized occluder by about
//   one cell, so cells of R / 4 keep that error within a quarter of R: N = ceil(L / (R / 4)) with L
//   the longest edge of the padded box.
// Both clamped to [8, 64]: below 8 a cube face or grid has too few texels to interpolate; 64 bounds
// the memory (cube 732 KB, grid6 6.3 MB).
#include "core/TriangleMesh.h"
#include "fields/FieldBakeSettings.h"

namespace aokit {

constexpr int kAutoResolutionMin = 8;
constexpr int kAutoResolutionMax = 64;

// Throws std::invalid_argument for a non-positive radius or an empty mesh.
int autoFieldResolution(const FieldBakeSettings& s, const TriangleMesh& mesh, double radius);

// s.resolution when set, else autoFieldResolution.
int resolveFieldResolution(const FieldBakeSettings& s, const TriangleMesh& mesh, double radius);

}  // namespace aokit
