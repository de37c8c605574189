#pragma once
// Triangles into a VoxelGrid on the CPU: the oracle that GPU voxelizations are tested against, and
// exact simulations of the two GPU strategies Hybrid AO can use (HybridSettings::frame).
//
//   Exact         every voxel whose closed cube the triangle meets (separating axis theorem).
//   ThreeAxis     conservative dominant-axis projection: the triangle is projected along the grid
//                 axis d where its normal is largest; every column whose closed square the projection
//                 meets (conservative rasterization) gets the voxels from floor(zmin) to floor(zmax),
//                 where [zmin, zmax] is the triangle plane's depth over the square's four corners,
//                 clamped to the triangle's own depth range. A superset of Exact; it equals Exact
//                 away from triangle edges (a plane over a square covers exactly that depth range).
//   ColumnCentre  the seed's rasterization (Eisemann & Decoret): an orthographic view along the grid's
//                 z axis; a column (i, j) whose centre (i + .5, j + .5) lies in the projected triangle
//                 gets the one voxel k = floor(z) at the triangle's depth there. Triangles parallel to
//                 z have no footprint and are lost, hence the seed's randomly rotated frame.
//   DominantCentre  ColumnCentre along each triangle's dominant axis (the usual GPU voxelizer
//                 without conservative rasterization: one voxel per covered column centre, k =
//                 floor(depth)). Thin (about one voxel) like ColumnCentre, but no triangle is lost
//                 and the voxels of a surface stay 26-connected, so no line crosses it unseen.
//
// Exact enumerates the ThreeAxis candidates and keeps those that pass the 3D overlap test, so its
// cost is about that of ThreeAxis times the test. Voxels outside the grid are dropped.
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "core/NodeVisitor.h"
#include "core/TriangleMesh.h"
#include "voxel/VoxelFrame.h"
#include "voxel/VoxelGrid.h"

namespace aokit {

enum class VoxelizeMethod { Exact, ThreeAxis, ColumnCentre, DominantCentre };

// One triangle given in grid coordinates (VoxelFrame::toGrid), ORed into `grid`.
void voxelizeTriangle(VoxelGrid& grid, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                      VoxelizeMethod method);

// Every triangle of `mesh` placed by `world`.
void voxelizeMesh(VoxelGrid& grid, const VoxelFrame& frame, const TriangleMesh& mesh, const glm::dmat4& world,
                  VoxelizeMethod method);

// A grid of frame.dims holding every instance (those without a mesh are skipped). With `solid`,
// the insides of watertight meshes are filled too (SolidVoxelizer.h: one parity grid for all of
// them, ORed in); with `trim` as well, their surface voxels outside that inside and beside it are
// dropped (VoxelGrid::mergeTrimmed; open meshes' voxels are kept). `progress`, if given, gets the
// fraction of instances done and may throw to cancel.
VoxelGrid voxelizeInstances(const std::vector<GeometryInstance>& instances, const VoxelFrame& frame,
                            VoxelizeMethod method, bool solid = false,
                            const std::function<void(double)>& progress = {}, bool trim = false);

}  // namespace aokit
