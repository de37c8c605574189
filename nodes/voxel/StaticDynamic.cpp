#include "voxel/StaticDynamic.h"

#include <stdexcept>

namespace aokit {

namespace {

void checkSizes(const std::vector<Bounds>& casters, const std::vector<bool>& isStatic) {
  if (casters.size() != isStatic.size())
    throw std::invalid_argument("static/dynamic: one static flag per caster is needed");
}

// Splits the region's casters into the plan's lists.
StaticDynamicPlan planOver(VoxelRegion region, const std::vector<bool>& isStatic) {
  StaticDynamicPlan plan;
  plan.region = std::move(region);
  if (plan.region.empty) return plan;
  plan.allCasters = plan.region.casters;
  for (std::size_t i : plan.allCasters) (isStatic[i] ? plan.staticCasters : plan.dynamicCasters).push_back(i);
  plan.memoryBytes = 2 * plan.region.memoryBytes;
  plan.empty = plan.dynamicCasters.empty();
  return plan;
}

}  // namespace

std::vector<Bounds> dynamicBoundsOnly(const std::vector<Bounds>& casters, const std::vector<bool>& isStatic) {
  checkSizes(casters, isStatic);
  std::vector<Bounds> out(casters.size());
  for (std::size_t i = 0; i < casters.size(); ++i)
    if (!isStatic[i]) out[i] = casters[i];
  return out;
}

StaticDynamicPlan planAroundDynamicRegion(const std::vector<Bounds>& casters, const std::vector<bool>& isStatic,
                                          const VoxelRegion& dyn, const Bounds& reach, const ViewFrustum& frustum,
                                          double R, const HybridSettings& settings) {
  checkSizes(casters, isStatic);
  validate(settings);
  if (dyn.empty) return StaticDynamicPlan{};
  // Grown by R (receivers and occluders within R of a dynamic caster), cut to the view's reach.
  Bounds box;
  for (std::size_t i : dyn.casters) box.extend(casters[i]);
  if (dyn.box.valid()) {  // the dynamic casters' part that the region kept (the budget may cut it)
    box.min = glm::max(box.min, dyn.box.min);
    box.max = glm::min(box.max, dyn.box.max);
  }
  box.min -= glm::dvec3(R);
  box.max += glm::dvec3(R);
  if (reach.valid()) {
    box.min = glm::max(box.min, reach.min);
    box.max = glm::min(box.max, reach.max);
  }
  if (!(box.max.x > box.min.x && box.max.y > box.min.y && box.max.z > box.min.z)) return StaticDynamicPlan{};
  HybridSettings fixed = settings;
  fixed.region = RegionMode::Box;
  fixed.regionBox = box;
  return planOver(computeVoxelRegion(casters, frustum, R, fixed), isStatic);
}

StaticDynamicPlan planStaticDynamic(const std::vector<Bounds>& casters, const std::vector<bool>& isStatic,
                                    const ViewFrustum& frustum, double R, const HybridSettings& settings) {
  checkSizes(casters, isStatic);
  validate(settings);
  if (settings.region == RegionMode::Box) return planOver(computeVoxelRegion(casters, frustum, R, settings), isStatic);
  // The dynamic casters near the view, as the auto region finds them.
  const VoxelRegion dyn = computeVoxelRegion(dynamicBoundsOnly(casters, isStatic), frustum, R, settings);
  Bounds reach = frustum.bounds();
  reach.min -= glm::dvec3(R);
  reach.max += glm::dvec3(R);
  return planAroundDynamicRegion(casters, isStatic, dyn, reach, frustum, R, settings);
}

}  // namespace aokit
