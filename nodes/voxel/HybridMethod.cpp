// The "hybrid" method (seed 004) in the method registry: its settings, once, and its bench curve.
#include <stdexcept>

#include "methods/MethodRegistry.h"
#include "reference/Falloff.h"
#include "voxel/HybridTechnique.h"

namespace aokit {
namespace {

const HybridSettings kDefaults;

std::shared_ptr<AOTechnique> make(const MethodSettings& s) {
  HybridSettings h;
  h.gridResolution = s.integer("res", h.gridResolution);
  h.memoryBudgetMiB = s.number("budget", h.memoryBudgetMiB);
  const int frame = s.choice("frame", -1);
  if (frame >= 0) h.frame = frame == 0 ? VoxelizingFrame::ThreeAxis : frame == 1 ? VoxelizingFrame::Rotated : VoxelizingFrame::DominantAxis;
  h.frameSeed = static_cast<std::uint32_t>(s.integer("seed", static_cast<int>(h.frameSeed)));
  h.solid = s.flag("solid", h.solid);
  h.snapToLattice = s.flag("lattice", h.snapToLattice);
  h.regionBudget = s.number("region", h.regionBudget);
  // A fixed region: all six of bx0, by0, bz0, bx1, by1, bz1 (world units).
  const char* boxKeys[6] = {"bx0", "by0", "bz0", "bx1", "by1", "bz1"};
  int given = 0;
  for (const char* k : boxKeys) given += s.has(k) ? 1 : 0;
  if (given != 0 && given != 6)
    throw std::invalid_argument("hybrid: a fixed region needs all of bx0, by0, bz0, bx1, by1, bz1");
  if (given == 6) {
    h.region = RegionMode::Box;
    for (int a = 0; a < 3; ++a) {
      h.regionBox.min[a] = s.number(boxKeys[a], 0.0);
      h.regionBox.max[a] = s.number(boxKeys[a + 3], 0.0);
    }
  }
  h.rays = s.integer("rays", h.rays);
  h.steps = s.integer("steps", h.steps);
  h.spanTest = s.flag("span", h.spanTest);
  h.scale = s.choice("scale", 0) == 0 ? AOMapScale::Half : AOMapScale::Quarter;
  h.spread = s.number("spread", h.spread);
  h.radius = s.number("radius", h.radius);
  if (s.has("falloff")) h.falloff = static_cast<Falloff>(s.choice("falloff", 0));
  h.normalOffset = s.number("offset", h.normalOffset);
  h.jitterCell = s.number("cell", h.jitterCell);
  h.filterSize = s.integer("filter", h.filterSize);
  h.normalSupport = s.number("hn", h.normalSupport);
  h.positionSupport = s.number("hp", h.positionSupport);
  h.aoSupport = s.number("ha", h.aoSupport);
  h.staticBake = s.flag("static", h.staticBake);
  h.bakeRays = s.integer("bakerays", h.bakeRays);
  h.view = static_cast<HybridView>(s.choice("view", 0));
  return std::make_shared<HybridTechnique>(h);
}

const MethodRegistrar registrar{{
    "hybrid",
    "Hybrid AO (seed 004): GPU voxelization of a region of interest, ray marching at low resolution, "
    "joint bilateral upsampling",
    30,
    {
        {"res", SettingKind::Integer, "voxels on the region's longest side", 64, 1024, {},
         std::to_string(kDefaults.gridResolution)},
        {"budget", SettingKind::Number, "MiB the grid may hold (res^3 checked before allocating)", 1e-3, 4096, {},
         defaultNumberText(kDefaults.memoryBudgetMiB)},
        {"frame", SettingKind::Choice, "voxelizer: conservative three-axis, the seed's rotated single direction, "
         "dominant axis", 0, 0, {"three-axis", "rotated", "dominant"}, "three-axis"},
        {"seed", SettingKind::Integer, "rotated frame: seed of the random rotation", 0, 2147483647, {},
         std::to_string(kDefaults.frameSeed)},
        {"solid", SettingKind::Flag, "fill the inside of closed casters", 0, 0, {}, kDefaults.solid ? "1" : "0"},
        {"lattice", SettingKind::Flag, "voxel size and origin on a fixed lattice (temporal stability)", 0, 0, {},
         kDefaults.snapToLattice ? "1" : "0"},
        {"region", SettingKind::Number, "longest side of the region of interest, units of R", 4, 1024, {},
         defaultNumberText(kDefaults.regionBudget)},
        {"bx0", SettingKind::Number, "fixed region instead of the view's: min x (with by0 ... bz1)", -1e30, 1e30, {},
         "view"},
        {"by0", SettingKind::Number, "fixed region: min y", -1e30, 1e30, {}, "view"},
        {"bz0", SettingKind::Number, "fixed region: min z", -1e30, 1e30, {}, "view"},
        {"bx1", SettingKind::Number, "fixed region: max x", -1e30, 1e30, {}, "view"},
        {"by1", SettingKind::Number, "fixed region: max y", -1e30, 1e30, {}, "view"},
        {"bz1", SettingKind::Number, "fixed region: max z", -1e30, 1e30, {}, "view"},
        {"rays", SettingKind::Integer, "rays per AO-map pixel", 1, 256, {},
         std::to_string(kDefaults.rays)},
        {"steps", SettingKind::Integer, "grid tests per ray", 1, 256, {}, std::to_string(kDefaults.steps)},
        {"span", SettingKind::Flag, "each step tests the voxels since the last one in its column", 0, 0, {},
         kDefaults.spanTest ? "1" : "0"},
        {"scale", SettingKind::Choice, "AO-map resolution: half or quarter", 0, 0, {"0.5", "0.25"}, "0.5"},
        {"spread", SettingKind::Number, "cone half-angle, fraction of 90 degrees", 1e-3, 1, {},
         defaultNumberText(kDefaults.spread)},
        {"radius", SettingKind::Number, "AO radius, world units (0 = the scene's)", 0, 1e30, {}, "scene"},
        {"falloff", SettingKind::Choice, "weight k(d) of a hit over the radius", 0, 0,
         {"binary", "wendland", "sqrt", "exponential"}, "scene"},
        {"offset", SettingKind::Number, "ray origins lifted along the normal, voxels", 0, 4, {},
         defaultNumberText(kDefaults.normalOffset)},
        {"cell", SettingKind::Number, "object-space jitter cell, voxels", 1e-3, 16, {}, defaultNumberText(kDefaults.jitterCell)},
        {"filter", SettingKind::Integer, "bilateral window m, full-resolution pixels (0 = own texel only)", 0, 64, {},
         std::to_string(kDefaults.filterSize)},
        {"hn", SettingKind::Number, "normal kernel support over 1 - n.n'", 1e-3, 2, {}, defaultNumberText(kDefaults.normalSupport)},
        {"hp", SettingKind::Number, "position kernel support, units of R", 1e-3, 4, {},
         defaultNumberText(kDefaults.positionSupport)},
        {"ha", SettingKind::Number, "AO kernel support", 1e-3, 1, {}, defaultNumberText(kDefaults.aoSupport)},
        {"static", SettingKind::Flag, "static geometry (node mask without kDynamic) baked per vertex once; "
         "the grids cover the dynamic casters' region", 0, 0, {}, kDefaults.staticBake ? "1" : "0"},
        {"bakerays", SettingKind::Integer, "static bake: rays per vertex", 1, 4096, {},
         std::to_string(kDefaults.bakeRays)},
        {"view", SettingKind::Choice, "debug view", 0, 0, {"none", "ao", "normals", "depth", "voxels"}, "none"},
    },
    // Curve, cheap to accurate: quarter resolution with few rays (the second and third err less
    // than vtkSSAOPass(32) on every default scene, in about its AO time or less at 1024 x 768),
    // then half resolution up to the seed's Table 1 (the defaults) and a finer grid.
    {"res=128,rays=8,steps=4,scale=0.25,filter=16", "res=256,rays=12,steps=5,scale=0.25,filter=12",
     "res=256,rays=16,steps=6,scale=0.25,filter=16", "res=256,rays=16,steps=8", "",
     "res=512,rays=32,steps=8,budget=128"},
    make,
}};

}  // namespace
}  // namespace aokit
