// The "hybrid" method (seed 004) in the method registry: its schema and its bench curve.
#include "methods/MethodRegistry.h"
#include "voxel/HybridTechnique.h"

namespace aokit {
namespace {

// Curve, cheap to accurate: quarter resolution with few rays, first with bilinear upsampling
// (the joint bilateral window costs more than the march there), then with the window, then the
// seed's Table 1 (32 rays, 8 steps, no stride, origins lifted 2 voxels: the defaults before the
// stride), the defaults (16 rays, at most 1.5 voxels a step), those with the seed's 32 rays and
// with at most one voxel a step, a finer grid (with 2.5 voxels a step and 32 rays, then the
// defaults), and a finer grid voxelized at voxel centres (not conservatively: casters not fattened
// by up to a voxel each side), and that with origins lifted 1 voxel.
const MethodRegistrar registrar{familyMethod(
    "hybrid",
    "Hybrid AO (seed 004): GPU voxelization of a region of interest, ray marching at low resolution, "
    "joint bilateral upsampling",
    30, hybridSchema(),
    {"res=128,rays=8,steps=4,scale=0.25,window=0", "res=128,rays=8,steps=4,scale=0.25,window=16", "res=256,rays=12,steps=5,scale=0.25,window=12",
     "res=256,rays=16,steps=6,scale=0.25,window=16", "rays=32,stride=0,offset=2", "", "rays=32", "stride=1",
     "res=512,rays=32,steps=8,stride=2.5,budget=128", "res=512", "res=512,frame=dominant",
     "res=512,frame=dominant,offset=1"},
    [](const HybridSettings& s) { return std::make_shared<HybridTechnique>(s); })};

}  // namespace
}  // namespace aokit
