#include "voxel/StaticDynamic.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace aokit {

namespace {

void checkSizes(const std::vector<Bounds>& casters, const std::vector<bool>& isStatic) {
  if (casters.size() != isStatic.size())
    throw std::invalid_argument("static/dynamic: one static flag per caster is needed");
}

double volume(const Bounds& b) {
  const glm::dvec3 s = glm::max(b.max - b.min, glm::dvec3(0.0));
  return s.x * s.y * s.z;
}

Bounds united(Bounds a, const Bounds& b) {
  a.extend(b);
  return a;
}

// Splits the region's casters into the plan's lists; zones around the dynamic ones, grown by R and
// three voxels (the conservative voxels reach one beyond a surface, the march's span tests one
// more, the ray origin sits two voxels off its surface along the normal).
StaticDynamicPlan planOver(VoxelRegion region, const std::vector<Bounds>& casters, const std::vector<bool>& isStatic,
                           double R) {
  StaticDynamicPlan plan;
  plan.region = std::move(region);
  if (plan.region.empty) return plan;
  plan.allCasters = plan.region.casters;
  for (std::size_t i : plan.allCasters) (isStatic[i] ? plan.staticCasters : plan.dynamicCasters).push_back(i);
  plan.memoryBytes = 2 * plan.region.memoryBytes;
  plan.empty = plan.dynamicCasters.empty();
  std::vector<Bounds> dynamicBoxes;
  for (std::size_t i : plan.dynamicCasters) dynamicBoxes.push_back(casters[i]);
  plan.zones = mergeZones(dynamicBoxes, R + 3.0 * plan.region.frame.voxelSize, kMaxDynamicZones);
  return plan;
}

}  // namespace

std::vector<Bounds> mergeZones(const std::vector<Bounds>& boxes, double by, int maxCount) {
  std::vector<Bounds> zones;
  for (Bounds b : boxes) {
    if (!b.valid()) continue;
    b.min -= glm::dvec3(by);
    b.max += glm::dvec3(by);
    zones.push_back(b);
  }
  if (zones.size() > 256) {
    Bounds all;
    for (const Bounds& b : zones) all.extend(b);
    return {all};
  }
  while (zones.size() > static_cast<std::size_t>(std::max(1, maxCount))) {
    std::size_t bi = 0, bj = 1;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < zones.size(); ++i)
      for (std::size_t j = i + 1; j < zones.size(); ++j) {
        const double added = volume(united(zones[i], zones[j])) - volume(zones[i]) - volume(zones[j]);
        if (added < best) {
          best = added;
          bi = i;
          bj = j;
        }
      }
    zones[bi] = united(zones[bi], zones[bj]);
    zones.erase(zones.begin() + static_cast<std::ptrdiff_t>(bj));
  }
  return zones;
}

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
  // The dynamic casters' part that their region kept (the budget may cut it).
  Bounds dynamicBox;
  for (std::size_t i : dyn.casters) dynamicBox.extend(casters[i]);
  if (dyn.box.valid()) {
    dynamicBox.min = glm::max(dynamicBox.min, dyn.box.min);
    dynamicBox.max = glm::min(dynamicBox.max, dyn.box.max);
  }
  // Grown by R (static occluders within R of a dynamic caster), cut to the view's reach; the grid
  // needs only the dynamic casters and the static casters' parts in there.
  Bounds grown = dynamicBox;
  grown.min -= glm::dvec3(R);
  grown.max += glm::dvec3(R);
  if (reach.valid()) {
    grown.min = glm::max(grown.min, reach.min);
    grown.max = glm::min(grown.max, reach.max);
  }
  if (!grown.valid()) return StaticDynamicPlan{};
  Bounds box = dynamicBox;
  for (std::size_t i = 0; i < casters.size(); ++i) {
    if (!isStatic[i] || !casters[i].valid()) continue;
    Bounds part;
    part.min = glm::max(casters[i].min, grown.min);
    part.max = glm::min(casters[i].max, grown.max);
    box.extend(part);  // nothing when they miss
  }
  box.min = glm::max(box.min, grown.min);
  box.max = glm::min(box.max, grown.max);
  if (!box.valid()) return StaticDynamicPlan{};
  HybridSettings fixed = settings;
  fixed.regionBox = box;
  return planOver(computeVoxelRegion(casters, frustum, R, fixed), casters, isStatic, R);
}

StaticDynamicPlan planStaticDynamic(const std::vector<Bounds>& casters, const std::vector<bool>& isStatic,
                                    const ViewFrustum& frustum, double R, const HybridSettings& settings) {
  checkSizes(casters, isStatic);
  validate(settings);
  if (hasFixedRegion(settings))
    return planOver(computeVoxelRegion(casters, frustum, R, settings), casters, isStatic, R);
  // The dynamic casters near the view, as the auto region finds them.
  const VoxelRegion dyn = computeVoxelRegion(dynamicBoundsOnly(casters, isStatic), frustum, R, settings);
  Bounds reach = frustum.bounds();
  reach.min -= glm::dvec3(R);
  reach.max += glm::dvec3(R);
  return planAroundDynamicRegion(casters, isStatic, dyn, reach, frustum, R, settings);
}

}  // namespace aokit
