// The "hybrid" method (seed 004) in the method registry: its schema and its bench curve.
#include "methods/MethodRegistry.h"
#include "voxel/HybridTechnique.h"

namespace aokit {
namespace {

// Curve, cheap to accurate: quarter resolution with few rays, first with bilinear upsampling
// (the joint bilateral window costs more than the march there: it errs less than vtkSSAOPass(32)
// in under half its AO time at 1024 x 768), then with the window (the third and fourth err less
// than vtkSSAOPass(32) on every default scene, in about its AO time or less), then half
// resolution up to the seed's Table 1 (the defaults), the defaults with at most 2.5 voxels a step
// (small scenes, whose grids are fine against R: isosurface, streamlines) and with at most one
// (sheets without thickness, one voxel thick in the grid, across x or y: the open box), a finer
// grid with each of the two, and a finer grid voxelized at voxel centres (not conservatively:
// casters not fattened by up to a voxel each side; the best hybrid figure on cfd), and that with
// origins lifted 1 voxel, not 2 (tank's best; curved casters self-occlude: sphere-plane errs twice
// as much).
const MethodRegistrar registrar{familyMethod(
    "hybrid",
    "Hybrid AO (seed 004): GPU voxelization of a region of interest, ray marching at low resolution, "
    "joint bilateral upsampling",
    30, hybridSchema(),
    {"res=128,rays=8,steps=4,scale=0.25,window=0", "res=128,rays=8,steps=4,scale=0.25,window=16", "res=256,rays=12,steps=5,scale=0.25,window=12",
     "res=256,rays=16,steps=6,scale=0.25,window=16", "res=256,rays=16,steps=8", "", "stride=2.5", "stride=1",
     "res=512,rays=32,steps=8,stride=2.5,budget=128", "res=512,stride=1", "res=512,frame=dominant",
     "res=512,frame=dominant,offset=1"},
    [](const HybridSettings& s) { return std::make_shared<HybridTechnique>(s); })};

}  // namespace
}  // namespace aokit
