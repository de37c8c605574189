#pragma once
// Static plus dynamic (issue 9 item 5, seed 004 section 4): static casters carry baked per-vertex AO
// (VertexAOBake.h, StaticBake.h) and the voxelizer covers only the dynamic region: the dynamic
// casters' bounds grown by R (nothing farther can be occluded by them, or occlude them), cut to
// the frustum's reach, and of that only the box holding the dynamic casters and the static ones'
// parts in it (a flat static floor does not make the grid R deeper). Two grids over it, one frame:
//   dynamic grid   the dynamic casters only: static receivers in the region march it and combine
//                  the result with their baked AO (their static-static AO is already baked);
//   full grid      every caster that meets the region: dynamic receivers march it (they are
//                  occluded by static geometry too, and carry no bake). The GPU holds it as the
//                  dynamic grid plus a static grid (the static casters meeting the region), ORed
//                  by the march, so that each caster is voxelized once.
// Static receivers outside the region use the bake alone, and so do those outside every zone: a
// zone is a dynamic caster's bounds grown by R and a margin for the march's voxel rounding (at
// most kMaxDynamicZones, the closest merged), so that a static floor between moving objects
// marches nothing where no dynamic caster is within R. Combination, the multiplicative blend
// of seed 000: A = 1 - (1 - A_baked)(1 - A_dynamic), exact if the directions each blocks were
// independent; it lies between the truth for nested occluders (max) and for occluders in disjoint
// directions (the sum, which it underestimates by A_baked A_dynamic).
#include <cstddef>
#include <vector>

#include "core/Bounds.h"
#include "voxel/HybridSettings.h"
#include "voxel/ViewFrustum.h"
#include "voxel/VoxelRegion.h"

namespace aokit {

constexpr int kMaxDynamicZones = 16;

struct StaticDynamicPlan {
  bool empty = true;                         // no dynamic caster near the view: bake only
  VoxelRegion region;                        // the dynamic region's grid (frame, memory of one grid)
  std::vector<std::size_t> dynamicCasters;   // into the dynamic grid
  std::vector<std::size_t> staticCasters;    // into the static grid: static ones meeting the region
  std::vector<std::size_t> allCasters;       // the full grid: both of the above
  std::vector<Bounds> zones;                 // where static receivers march (world boxes)
  std::size_t memoryBytes = 0;               // both grids
};

// casterBounds: world bounds per caster; isStatic: the same length, true for baked casters.
// Validates the settings. In Auto mode the region is the dynamic one (the settings' budget cuts the
// dynamic casters' part of it as in computeVoxelRegion); in Box mode it is the settings' box.
StaticDynamicPlan planStaticDynamic(const std::vector<Bounds>& casterBounds, const std::vector<bool>& isStatic,
                                    const ViewFrustum& frustum, double R, const HybridSettings& settings);

// The same from a region of the dynamic casters already found (indices into casterBounds; the
// caller's own region function, e.g. for a parallel view), and the reach of the view (the frustum's
// bounds grown by R) that the grown region is cut to.
StaticDynamicPlan planAroundDynamicRegion(const std::vector<Bounds>& casterBounds, const std::vector<bool>& isStatic,
                                          const VoxelRegion& dynamicRegion, const Bounds& reach,
                                          const ViewFrustum& frustum, double R, const HybridSettings& settings);

// Boxes grown by `by`, merged (least added volume first) until at most `maxCount` remain; more
// than 256 boxes become their one bounding box.
std::vector<Bounds> mergeZones(const std::vector<Bounds>& boxes, double by, int maxCount);

// The bounds of the dynamic casters alone (static ones invalid), same indices.
std::vector<Bounds> dynamicBoundsOnly(const std::vector<Bounds>& casterBounds, const std::vector<bool>& isStatic);

inline float combineBakedAndDynamic(float baked, float dynamicAO) { return 1.0f - (1.0f - baked) * (1.0f - dynamicAO); }

}  // namespace aokit
