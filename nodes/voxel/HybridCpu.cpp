#include "voxel/HybridCpu.h"

#include <stdexcept>

#include "core/NodeVisitor.h"
#include "core/Scene.h"
#include "render/BilateralUpsample.h"
#include "voxel/CpuVoxelizer.h"
#include "voxel/HybridMarch.h"

namespace aokit {

namespace {

VoxelizeMethod methodFor(const HybridSettings& s) {
  return s.frame == VoxelizingFrame::Rotated        ? VoxelizeMethod::ColumnCentre
         : s.frame == VoxelizingFrame::DominantAxis ? VoxelizeMethod::DominantCentre
                                                    : VoxelizeMethod::ThreeAxis;
}

std::vector<GeometryInstance> pick(const std::vector<GeometryInstance>& all, const std::vector<std::size_t>& which) {
  std::vector<GeometryInstance> out;
  for (std::size_t i : which) out.push_back(all[i]);
  return out;
}

bool inAnyZone(const std::vector<Bounds>& zones, const glm::vec3& o) {
  for (const Bounds& z : zones) {
    const glm::vec3 lo(z.min), hi(z.max);  // float, as the shader's uniforms
    if (o.x >= lo.x && o.y >= lo.y && o.z >= lo.z && o.x <= hi.x && o.y <= hi.y && o.z <= hi.z) return true;
  }
  return false;
}

// The static mode's low-resolution march: each texel with the grids its receiver needs.
AOBuffer marchStaticDynamic(HybridCpuResult& out, const std::vector<GeometryInstance>& all, const SurfaceSamples& full,
                            const SurfaceSamples& low, int k, const HybridSettings& s, const FrameContext& context,
                            const std::vector<std::uint8_t>& dynamicReceivers, const Camera& camera) {
  const VoxelGrid dynamicGrid = voxelizeInstances(pick(all, out.plan.dynamicCasters), out.region.frame, methodFor(s),
                                                  s.solid, {}, s.trimShell);
  VoxelGrid fullGrid = voxelizeInstances(pick(all, out.plan.staticCasters), out.region.frame, methodFor(s), s.solid,
                                         {}, s.trimShell);
  for (std::size_t w = 0; w < fullGrid.words().size(); ++w) fullGrid.words()[w] |= dynamicGrid.words()[w];
  out.voxels = fullGrid.count();
  HybridMarchConstants c = makeHybridMarchConstants(s, context, out.region.frame);
  setViewer(c, camera);
  // Two batches over the same texels: dynamic receivers on the full grid, static ones near a
  // dynamic caster on the dynamic grid; the rest stay 0.
  SurfaceSamples dynamicPart = low, staticPart = low;
  for (int j = 0; j < low.height; ++j)
    for (int i = 0; i < low.width; ++i) {
      const std::size_t t = low.index(i, j);
      if (!low.covered[t]) continue;
      const int x = std::min(k * i + (k - 1) / 2, full.width - 1), y = std::min(k * j + (k - 1) / 2, full.height - 1);
      const bool dynamic = !dynamicReceivers.empty() && dynamicReceivers[full.index(x, y)];
      const bool near = inAnyZone(out.plan.zones, low.position[t] + c.normalOffset * low.normal[t]);
      dynamicPart.covered[t] = dynamic ? 1 : 0;
      staticPart.covered[t] = (!dynamic && near) ? 1 : 0;
    }
  AOBuffer lowAO = marchHybridAO(fullGrid, c, dynamicPart);
  const AOBuffer staticAO = marchHybridAO(dynamicGrid, c, staticPart);
  for (std::size_t t = 0; t < low.pixelCount(); ++t) {
    if (staticPart.covered[t]) lowAO.ao[t] = staticAO.ao[t];
    lowAO.covered[t] = low.covered[t];  // far static texels: AO 0
  }
  return lowAO;
}

}  // namespace

HybridCpuResult computeHybridAOCpu(Node& root, const Camera& camera, const SurfaceSamples& gbuffer, double sceneRadius,
                                   Falloff sceneFalloff, const HybridSettings& s,
                                   const std::vector<std::uint8_t>& dynamicReceivers) {
  validate(s);
  gbuffer.validate();
  if (gbuffer.width < 1 || gbuffer.height < 1) throw std::invalid_argument("hybrid: the G-buffer is empty");
  if (!dynamicReceivers.empty() && dynamicReceivers.size() != gbuffer.pixelCount())
    throw std::invalid_argument("hybrid: one dynamic-receiver flag per G-buffer pixel is needed");
  const FrameContext context = frameContext(s.common, sceneRadius, sceneFalloff);
  const double R = context.radius;
  HybridCpuResult out;
  out.ao.resize(gbuffer.width, gbuffer.height);

  const std::vector<GeometryInstance> all = collectInstances(root, kCastsAO);
  const Bounds scene = worldBounds(root);
  if (!scene.valid()) return out;
  const ViewFrustum frustum =
      ViewFrustum::covering(camera, static_cast<double>(gbuffer.width) / gbuffer.height, scene);
  if (s.staticBake) {
    std::vector<bool> isStatic;
    for (const auto& inst : all) isStatic.push_back((inst.mask & kDynamic) == 0);
    out.plan = planStaticDynamic(instanceBounds(all), isStatic, frustum, R, s);
    out.region = out.plan.region;
    if (out.plan.empty) out.region.empty = true;
  } else {
    out.region = computeVoxelRegion(instanceBounds(all), frustum, R, s);
  }
  if (out.region.empty) {
    for (std::size_t i = 0; i < gbuffer.pixelCount(); ++i) out.ao.covered[i] = gbuffer.covered[i];
    return out;
  }
  const int k = static_cast<int>(s.common.scale);
  const SurfaceSamples low = lowResolutionSamples(gbuffer, k);
  AOBuffer lowAO;
  if (s.staticBake) {
    lowAO = marchStaticDynamic(out, all, gbuffer, low, k, s, context, dynamicReceivers, camera);
  } else {
    const VoxelGrid grid = voxelizeInstances(pick(all, out.region.casters), out.region.frame, methodFor(s), s.solid, {},
                                             s.trimShell);
    out.voxels = grid.count();
    HybridMarchConstants c = makeHybridMarchConstants(s, context, out.region.frame);
    setViewer(c, camera);
    lowAO = marchHybridAO(grid, c, low);
  }
  const UpsampleSettings& u = s.common.upsample;
  if (u.window < 1) throw std::invalid_argument("hybrid: the CPU oracle upsamples with the bilateral filter only (window >= 1)");
  BilateralParams p;
  p.scale = k;
  p.filterSize = u.window;
  p.normalSupport = static_cast<float>(u.normalSupport);
  p.positionSupport = static_cast<float>(u.positionSupport * R);
  p.aoSupport = static_cast<float>(u.aoSupport);
  out.ao = jointBilateralUpsample(lowAO, low, gbuffer, p);
  return out;
}

}  // namespace aokit
