#pragma once
// The whole Hybrid AO method on the CPU, stage for stage as the GPU pass will run it: region of
// interest -> voxelization (the strategy of HybridSettings::frame) -> march at the AO-map scale ->
// joint bilateral upsampling. The oracle for GPU-vs-CPU tests of the full pass, and a way to
// measure the method against the reference without GL.
#include "core/Camera.h"
#include "core/Node.h"
#include "reference/SurfaceSamples.h"
#include "voxel/HybridSettings.h"
#include "voxel/VoxelRegion.h"

namespace aokit {

struct HybridCpuResult {
  AOBuffer ao;             // full resolution, on the covered pixels of the G-buffer
  VoxelRegion region;      // what was voxelized, the grid's frame and memory
  std::size_t voxels = 0;  // set voxels
};

// Casters: every Geometry under `root` with kCastsAO. The frustum covers the scene's bounds with the
// G-buffer's aspect. R and the falloff are the scene's unless the settings give them. Throws
// std::invalid_argument on bad settings or buffers.
HybridCpuResult computeHybridAOCpu(Node& root, const Camera& camera, const SurfaceSamples& gbuffer, double sceneRadius,
                                   Falloff sceneFalloff, const HybridSettings& settings);

}  // namespace aokit
