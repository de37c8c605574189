#include "voxel/HybridCpu.h"

#include <stdexcept>

#include "core/NodeVisitor.h"
#include "core/Scene.h"
#include "voxel/BilateralUpsample.h"
#include "voxel/CpuVoxelizer.h"
#include "voxel/HybridMarch.h"

namespace aokit {

HybridCpuResult computeHybridAOCpu(Node& root, const Camera& camera, const SurfaceSamples& gbuffer, double sceneRadius,
                                   Falloff sceneFalloff, const HybridSettings& s) {
  validate(s);
  gbuffer.validate();
  if (gbuffer.width < 1 || gbuffer.height < 1) throw std::invalid_argument("hybrid: the G-buffer is empty");
  const double R = s.radius > 0.0 ? s.radius : sceneRadius;
  HybridCpuResult out;
  out.ao.resize(gbuffer.width, gbuffer.height);

  const std::vector<GeometryInstance> all = collectInstances(root, kCastsAO);
  const Bounds scene = worldBounds(root);
  if (!scene.valid()) return out;
  const ViewFrustum frustum =
      ViewFrustum::covering(camera, static_cast<double>(gbuffer.width) / gbuffer.height, scene);
  out.region = computeVoxelRegion(instanceBounds(all), frustum, R, s);
  if (out.region.empty) {
    for (std::size_t i = 0; i < gbuffer.pixelCount(); ++i) out.ao.covered[i] = gbuffer.covered[i];
    return out;
  }
  std::vector<GeometryInstance> casters;
  for (std::size_t i : out.region.casters) casters.push_back(all[i]);
  const VoxelizeMethod method = s.frame == VoxelizingFrame::Rotated        ? VoxelizeMethod::ColumnCentre
                                : s.frame == VoxelizingFrame::DominantAxis ? VoxelizeMethod::DominantCentre
                                                                           : VoxelizeMethod::ThreeAxis;
  const VoxelGrid grid = voxelizeInstances(casters, out.region.frame, method, s.solid);
  out.voxels = grid.count();

  const int k = static_cast<int>(s.scale);
  const SurfaceSamples low = lowResolutionSamples(gbuffer, k);
  const HybridMarchConstants c = makeHybridMarchConstants(s, sceneRadius, sceneFalloff, out.region.frame);
  const AOBuffer lowAO = marchHybridAO(grid, c, low);
  BilateralParams p;
  p.scale = k;
  p.filterSize = std::max(1, s.filterSize);
  p.normalSupport = static_cast<float>(s.normalSupport);
  p.positionSupport = static_cast<float>(s.positionSupport * R);
  p.aoSupport = static_cast<float>(s.aoSupport);
  out.ao = jointBilateralUpsample(lowAO, low, gbuffer, p);
  return out;
}

}  // namespace aokit
