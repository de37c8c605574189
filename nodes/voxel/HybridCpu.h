#pragma once
// The whole Hybrid AO method on the CPU, stage for stage as the GPU pass will run it: region of
// interest -> voxelization (the strategy of HybridSettings::frame) -> march at the AO-map scale ->
// joint bilateral upsampling. The oracle for GPU-vs-CPU tests of the full pass, and a way to
// measure the method against the reference without GL.
// With settings.staticBake, the static/dynamic plan (StaticDynamic.h; casters whose effective mask
// lacks kDynamic are static): the dynamic casters' grid and the static casters' grid over the
// dynamic region; receivers flagged dynamic march both, static ones the dynamic grid inside the
// zones and nothing elsewhere. The result is then the dynamic part only: the baked AO is combined
// afterwards (the G-buffer's, as the GPU pass's combine stage does).
#include <cstdint>
#include <vector>

#include "core/Camera.h"
#include "core/Node.h"
#include "reference/SurfaceSamples.h"
#include "voxel/HybridSettings.h"
#include "voxel/StaticDynamic.h"
#include "voxel/VoxelRegion.h"

namespace aokit {

struct HybridCpuResult {
  AOBuffer ao;             // full resolution, on the covered pixels of the G-buffer
  VoxelRegion region;      // what was voxelized, the grid's frame and memory
  std::size_t voxels = 0;  // set voxels (static mode: of both grids)
  StaticDynamicPlan plan;  // static mode only
};

// Casters: every Geometry under `root` with kCastsAO. The frustum covers the scene's bounds with the
// G-buffer's aspect. R and the falloff are the scene's unless the settings give them.
// dynamicReceivers (static mode): per G-buffer pixel, nonzero where the receiver is dynamic (the
// G-buffer's AO_FLAG_DYNAMIC); empty = every receiver static. Throws std::invalid_argument on bad
// settings or buffers.
HybridCpuResult computeHybridAOCpu(Node& root, const Camera& camera, const SurfaceSamples& gbuffer, double sceneRadius,
                                   Falloff sceneFalloff, const HybridSettings& settings,
                                   const std::vector<std::uint8_t>& dynamicReceivers = {});

}  // namespace aokit
