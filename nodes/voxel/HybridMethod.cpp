// The "hybrid" method (seed 004) in the method registry: its schema and its bench curve.
#include "methods/MethodRegistry.h"
#include "voxel/HybridTechnique.h"

namespace aokit {
namespace {

// Curve, cheap to accurate: quarter resolution with few rays, first with bilinear upsampling
// (the joint bilateral window costs more than the march there), then with the window, then the
// seed's Table 1 (res 256, conservative three-axis voxels, 32 rays, 8 steps, no stride, origins
// lifted 2 voxels), conservative voxels at res 256 with 1.5 voxels a step and a 1.5-voxel lift, the
// defaults at res 256, the defaults (res 384, voxels at column centres along each triangle's
// dominant axis, 16 rays, at most one voxel a step, lifted one), those with 32 rays and with rays
// from the surface (lift=ray), a finer grid (the defaults, conservative, with 32 rays), and last
// rays from the surface at full resolution: the most accurate point (tank, cfd), at ~3.5x the
// defaults' AO time.
const MethodRegistrar registrar{familyMethod(
    "hybrid",
    "Hybrid AO (seed 004): GPU voxelization of a region of interest, ray marching at low resolution, "
    "joint bilateral upsampling",
    30, hybridSchema(),
    {"res=128,rays=8,steps=4,scale=0.25,window=0", "res=128,rays=8,steps=4,scale=0.25,window=16", "res=256,rays=12,steps=5,scale=0.25,window=12",
     "res=256,rays=16,steps=6,scale=0.25,window=16", "res=256,rays=32,stride=0,offset=2,frame=three-axis",
     "res=256,frame=three-axis,stride=1.5,offset=1.5", "res=256", "", "rays=32", "lift=ray", "res=512", "res=512,frame=three-axis,stride=1.5,offset=1.5",
     "res=512,rays=32", "scale=1,lift=ray"},
    [](const HybridSettings& s) { return std::make_shared<HybridTechnique>(s); })};

}  // namespace
}  // namespace aokit
