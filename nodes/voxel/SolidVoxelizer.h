#pragma once
// Solid voxelization of closed casters (Eisemann & Decoret 2006, parity by XOR): the inside of a
// watertight mesh is filled, so that a ray march with few, long steps cannot step over a hollow
// shell one or two voxels thick into an empty interior and miss the occluder.
//
// GPU: one orthographic pass along the grid's z axis with glLogicOp(GL_XOR) (or imageAtomicXor)
// and depth clamping (GL_DEPTH_CLAMP, so parts before or behind the grid still count). A fragment
// at column (i, j) and depth z flips every voxel whose centre lies behind it: k + 0.5 > z, i.e.
// k >= floor(z - 0.5) + 1. After all closed casters, a voxel is set iff its centre has an odd
// number of surfaces in front of it along the column: inside. All closed casters share one parity
// target, so where two of them overlap the overlap reads as empty (their surfaces, voxelized as
// usual and ORed in, still bound it). Open meshes (a floor plane) are never parity-filled.
#include "core/TriangleMesh.h"
#include "voxel/VoxelFrame.h"
#include "voxel/VoxelGrid.h"

namespace aokit {

// True when every edge, after welding vertices of (nearly: 2^-20 of the mesh size) equal position,
// is used by exactly two triangles in opposite directions: a closed, consistently oriented surface.
bool isWatertight(const TriangleMesh& mesh);

// XORs the mesh's parity fragments into `parity` (sized frame.dims).
void fillSolidParity(VoxelGrid& parity, const VoxelFrame& frame, const TriangleMesh& mesh, const glm::dmat4& world);

}  // namespace aokit
