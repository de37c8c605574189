#pragma once
// The region of interest of the voxelizer (issue 9 item 2) and the grid that covers it: a pure
// function of the casters' world bounds, the view frustum, the AO radius R and the settings.
//
// Auto: receivers are what the camera sees, so the occluders that matter lie within R of the view
// frustum, and only the part of them within R of the frustum's bounding box. The region is the
// union of those parts: occluders just off screen or behind the camera stay inside. When its
// longest side exceeds the budget (regionBudget R), the frustum is cut at the largest view depth
// D whose region fits: receivers deeper than D get no hybrid AO (coveredDepth says where), the
// near field keeps its voxel size. Box: the given world box.
//
// Voxel size follows: longest side / gridResolution (<= regionBudget R / gridResolution in Auto),
// or, with snapToLattice, the next step of a 2^(1/8) ladder above longest side / (gridResolution - 1)
// with the origin on that lattice. A rotated frame (VoxelizingFrame::Rotated) covers the region
// with a box in its own axes.
#include <cstddef>
#include <vector>

#include "core/Bounds.h"
#include "core/NodeVisitor.h"
#include "voxel/HybridSettings.h"
#include "voxel/ViewFrustum.h"
#include "voxel/VoxelFrame.h"

namespace aokit {

struct VoxelRegion {
  bool empty = true;                  // no caster near the view: nothing to voxelize, AO 0
  Bounds box;                         // world box the grid must cover
  VoxelFrame frame;                   // the grid over it (dims <= gridResolution per axis)
  std::size_t memoryBytes = 0;        // of the packed grid (VoxelGrid.h), exact
  std::vector<std::size_t> casters;   // indices (into the input) of the casters to voxelize
  double coveredDepth = 0.0;          // view depth up to which receivers are inside (Auto)
  bool clipped = false;               // the budget cut the frustum
};

// casterBounds: world bounds of each caster (invalid bounds are skipped). R > 0. Validates the
// settings first (throws std::invalid_argument with the settings' one-line message).
VoxelRegion computeVoxelRegion(const std::vector<Bounds>& casterBounds, const ViewFrustum& frustum, double R,
                               const HybridSettings& settings);

// World bounds of each instance's mesh (invalid for instances without one).
std::vector<Bounds> instanceBounds(const std::vector<GeometryInstance>& instances);

}  // namespace aokit
