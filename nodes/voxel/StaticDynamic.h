#pragma once
// Static plus dynamic (issue 9 item 5, seed 004 section 4): static casters carry baked per-vertex AO
// (VertexAOBake.h) and the voxelizer covers only the dynamic region, the dynamic casters' bounds
// grown by R (nothing farther can be occluded by them, or occlude them), cut to the frustum's reach.
// Two grids over that region, one frame:
//   dynamic grid   the dynamic casters only: static receivers in the region march it and combine
//                  the result with their baked AO (their static-static AO is already baked);
//   full grid      every caster that meets the region: dynamic receivers march it (they are
//                  occluded by static geometry too, and carry no bake).
// Static receivers outside the region use the bake alone. Combination, the multiplicative blend
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

struct StaticDynamicPlan {
  bool empty = true;                         // no dynamic caster near the view: bake only
  VoxelRegion region;                        // the dynamic region's grid (frame, memory of one grid)
  std::vector<std::size_t> dynamicCasters;   // into the dynamic grid
  std::vector<std::size_t> allCasters;       // into the full grid: dynamic and static meeting the region
  std::size_t memoryBytes = 0;               // both grids
};

// casterBounds: world bounds per caster; isStatic: the same length, true for baked casters.
// Validates the settings; their region mode is ignored (the region is the dynamic one).
StaticDynamicPlan planStaticDynamic(const std::vector<Bounds>& casterBounds, const std::vector<bool>& isStatic,
                                    const ViewFrustum& frustum, double R, const HybridSettings& settings);

inline float combineBakedAndDynamic(float baked, float dynamicAO) { return 1.0f - (1.0f - baked) * (1.0f - dynamicAO); }

}  // namespace aokit
