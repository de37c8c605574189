#include "voxel/HybridSettings.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace aokit {

std::size_t packedGridBytes(int nx, int ny, int nz) {
  if (nx <= 0 || ny <= 0 || nz <= 0) return 0;
  const std::size_t slabs = (static_cast<std::size_t>(nz) + 127) / 128;
  return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * slabs * 16;
}

bool hasFixedRegion(const HybridSettings& s) {
  return s.regionBox.min != glm::dvec3(0.0) || s.regionBox.max != glm::dvec3(0.0);
}

namespace {

double gridMiB(const HybridSettings& s) {
  return packedGridBytes(s.gridResolution, s.gridResolution, s.gridResolution) / (1024.0 * 1024.0);
}

// The schema's rule message cannot hold numbers; validate() says them.
void checkBudget(const HybridSettings& s) {
  if (gridMiB(s) <= s.memoryBudgetMiB) return;
  std::ostringstream msg;
  msg << "hybrid: a " << s.gridResolution << "^3 grid needs " << gridMiB(s) << " MiB, over the memory budget of "
      << s.memoryBudgetMiB << " MiB (raise the budget, or lower the resolution)";
  throw std::invalid_argument(msg.str());
}

}  // namespace

const Schema<HybridSettings>& hybridSchema() {
  static const Schema<HybridSettings> schema = [] {
    using S = HybridSettings;
    Schema<S> t("hybrid");
    includeDeferred(t, {{AOScale::Full, AOScale::Half, AOScale::Quarter},
                        {DebugView::Off, DebugView::AO, DebugView::Normals, DebugView::Depth, DebugView::Voxels}});
    t.integer("res", &S::gridResolution, 64, 1024, "voxels on the region's longest side");
    t.number("budget", &S::memoryBudgetMiB, Interval::aboveZero(4096), "MiB the grid may hold (res^3 checked before allocating)");
    t.choice("frame", &S::frame,
             {{"three-axis", VoxelizingFrame::ThreeAxis}, {"rotated", VoxelizingFrame::Rotated},
              {"dominant", VoxelizingFrame::DominantAxis}},
             "voxelizer: conservative three-axis, the seed's rotated single direction, dominant axis");
    t.integer("seed", &S::frameSeed, 0, 2147483647, "rotated frame: seed of the random rotation");
    t.flag("solid", &S::solid, "fill the inside of closed casters");
    t.flag("trim", &S::trimShell,
           "with solid: closed casters' surface voxels outside them, beside an inside voxel, dropped (not fattened)");
    t.flag("lattice", &S::snapToLattice, "voxel size and origin on a fixed lattice (temporal stability)");
    t.number("region", &S::regionBudget, Interval::closed(4, 1024), "longest side of the view's region of interest, units of R");
    const char* axes = "xyz";
    for (int a = 0; a < 3; ++a) {
      t.number(std::string("b") + axes[a] + "0", [a](auto& s) -> auto& { return s.regionBox.min[a]; },
               Interval::closed(-1e15, 1e15), std::string("fixed region instead of the view's: min ") + axes[a] +
                                                 " (all six of bx0..bz1, or none)");
    }
    for (int a = 0; a < 3; ++a) {
      t.number(std::string("b") + axes[a] + "1", [a](auto& s) -> auto& { return s.regionBox.max[a]; },
               Interval::closed(-1e15, 1e15), std::string("fixed region: max ") + axes[a]);
    }
    t.integer("rays", &S::rays, 1, 256, "rays per AO-map pixel");
    t.integer("steps", &S::steps, 1, 256, "grid tests per ray");
    t.number("stride", &S::stride, Interval::closed(0, 64),
             "most voxels one step may cross (more steps where R / steps is longer, up to 256); 0: steps as set");
    t.flag("span", &S::spanTest, "each step tests the voxels since the last one in its column");
    t.flag("segment", &S::segmentTest,
           "rays walked column by column, each column over the depth the ray spends in it: every voxel a ray passes, no steps (about 1.3x the AO time)");
    t.number("spread", &S::spread, Interval::aboveZero(1), "cone half-angle, fraction of 90 degrees");
    t.number("offset", &S::normalOffset, Interval::closed(0, 4), "ray origins lifted along the normal, voxels");
    t.choice("lift", &S::lift, {{"normal", RayLift::Normal}, {"ray", RayLift::Ray}, {"graze", RayLift::Graze}},
             "normal: ray origins lifted along the normal by the offset; ray: rays from the surface, "
             "steps below the offset above its tangent plane skipped; graze: each ray lifted by offset (1 - cos), "
             "then as ray");
    t.number("reach", &S::reach, Interval::closed(1, 64), "graze: each ray lifted by offset (1 - reach cos), at least 0");
    t.number("cell", &S::jitterCell, Interval::aboveZero(16), "object-space jitter cell, voxels");
    t.integer("noise", &S::jitterSeed, 0, 4294967295LL, "seed of the jitter noise pattern");
    t.flag("static", &S::staticBake,
           "static geometry (node mask without kDynamic) baked per vertex once; the grids cover the dynamic casters' region");
    t.integer("bakerays", &S::bakeRays, 1, 4096, "static bake: rays per vertex");
    t.rule([](const S& s) {
      const Bounds& b = s.regionBox;
      return !hasFixedRegion(s) || (b.max.x > b.min.x && b.max.y > b.min.y && b.max.z > b.min.z);
    }, "a fixed region needs all of bx0, by0, bz0, bx1, by1, bz1, a box of positive volume");
    return t;
  }();
  return schema;
}

void validate(const HybridSettings& s) {
  hybridSchema().validate(s);
  checkBudget(s);
}

}  // namespace aokit
