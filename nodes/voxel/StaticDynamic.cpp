#include "voxel/StaticDynamic.h"

#include <stdexcept>

namespace aokit {

StaticDynamicPlan planStaticDynamic(const std::vector<Bounds>& casters, const std::vector<bool>& isStatic,
                                    const ViewFrustum& frustum, double R, const HybridSettings& settings) {
  if (casters.size() != isStatic.size())
    throw std::invalid_argument("static/dynamic: one static flag per caster is needed");
  validate(settings);
  StaticDynamicPlan plan;
  // The dynamic casters near the view, as the auto region finds them.
  std::vector<Bounds> dynamicOnly(casters.size());
  for (std::size_t i = 0; i < casters.size(); ++i)
    if (!isStatic[i]) dynamicOnly[i] = casters[i];
  HybridSettings autoRegion = settings;
  autoRegion.region = RegionMode::Auto;
  const VoxelRegion dyn = computeVoxelRegion(dynamicOnly, frustum, R, autoRegion);
  if (dyn.empty) return plan;
  // Grown by R (receivers and occluders within R of a dynamic caster), cut to the frustum's reach.
  Bounds box;
  for (std::size_t i : dyn.casters) box.extend(casters[i]);
  box.min -= glm::dvec3(R);
  box.max += glm::dvec3(R);
  Bounds reach = frustum.bounds();
  reach.min -= glm::dvec3(R);
  reach.max += glm::dvec3(R);
  box.min = glm::max(box.min, reach.min);
  box.max = glm::min(box.max, reach.max);
  if (!(box.max.x > box.min.x && box.max.y > box.min.y && box.max.z > box.min.z)) return plan;
  HybridSettings fixed = settings;
  fixed.region = RegionMode::Box;
  fixed.regionBox = box;
  plan.region = computeVoxelRegion(casters, frustum, R, fixed);
  if (plan.region.empty) return plan;
  plan.allCasters = plan.region.casters;
  for (std::size_t i : plan.allCasters)
    if (!isStatic[i]) plan.dynamicCasters.push_back(i);
  plan.memoryBytes = 2 * plan.region.memoryBytes;
  plan.empty = plan.dynamicCasters.empty();
  return plan;
}

}  // namespace aokit
