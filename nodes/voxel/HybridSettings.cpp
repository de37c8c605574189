#include "voxel/HybridSettings.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace aokit {

namespace {
[[noreturn]] void fail(const std::string& field, const std::string& rule, double got) {
  std::ostringstream msg;
  msg << "hybrid: " << field << " must be " << rule << ", got " << got;
  throw std::invalid_argument(msg.str());
}
bool finite(double v) { return std::isfinite(v); }
bool inRange(double v, double lo, double hi) { return finite(v) && v >= lo && v <= hi; }
bool inOpenClosed(double v, double lo, double hi) { return finite(v) && v > lo && v <= hi; }
}  // namespace

std::size_t packedGridBytes(int nx, int ny, int nz) {
  if (nx <= 0 || ny <= 0 || nz <= 0) return 0;
  const std::size_t slabs = (static_cast<std::size_t>(nz) + 127) / 128;
  return static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * slabs * 16;
}

void validate(const HybridSettings& s) {
  if (s.gridResolution < 64 || s.gridResolution > 1024) fail("gridResolution", "in 64..1024", s.gridResolution);
  if (!inOpenClosed(s.memoryBudgetMiB, 0.0, 4096.0)) fail("memoryBudgetMiB", "in (0, 4096]", s.memoryBudgetMiB);
  const double needMiB = packedGridBytes(s.gridResolution, s.gridResolution, s.gridResolution) / (1024.0 * 1024.0);
  if (needMiB > s.memoryBudgetMiB) {
    std::ostringstream msg;
    msg << "hybrid: a " << s.gridResolution << "^3 grid needs " << needMiB << " MiB, over the memory budget of "
        << s.memoryBudgetMiB << " MiB (raise the budget, or lower the resolution)";
    throw std::invalid_argument(msg.str());
  }
  if (s.frame != VoxelizingFrame::ThreeAxis && s.frame != VoxelizingFrame::Rotated &&
      s.frame != VoxelizingFrame::DominantAxis)
    fail("frame", "ThreeAxis, Rotated or DominantAxis", static_cast<int>(s.frame));
  if (s.region == RegionMode::Box) {
    const Bounds& b = s.regionBox;
    const bool finiteBox = finite(b.min.x) && finite(b.min.y) && finite(b.min.z) && finite(b.max.x) &&
                           finite(b.max.y) && finite(b.max.z);
    if (!finiteBox || !(b.max.x > b.min.x && b.max.y > b.min.y && b.max.z > b.min.z))
      throw std::invalid_argument("hybrid: regionBox must be a finite box of positive volume in Box mode");
  } else if (s.region != RegionMode::Auto) {
    fail("region", "Auto or Box", static_cast<int>(s.region));
  }
  if (!inRange(s.regionBudget, 4.0, 1024.0)) fail("regionBudget", "in 4..1024 (units of R)", s.regionBudget);
  if (s.rays < 1 || s.rays > 256) fail("rays", "in 1..256", s.rays);
  if (s.steps < 1 || s.steps > 256) fail("steps", "in 1..256", s.steps);
  if (s.scale != AOMapScale::Half && s.scale != AOMapScale::Quarter)
    fail("scale", "2 (half) or 4 (quarter)", static_cast<int>(s.scale));
  if (!inOpenClosed(s.spread, 0.0, 1.0)) fail("spread", "in (0, 1] (a fraction of 90 degrees)", s.spread);
  if (!finite(s.radius) || s.radius < 0.0) fail("radius", ">= 0 (0 = the scene's AO radius)", s.radius);
  if (!inRange(s.normalOffset, 0.0, 4.0)) fail("normalOffset", "in 0..4 (voxels)", s.normalOffset);
  if (!inOpenClosed(s.jitterCell, 0.0, 16.0)) fail("jitterCell", "in (0, 16] (voxels)", s.jitterCell);
  if (s.filterSize < 0 || s.filterSize > 64) fail("filterSize", "in 0..64 (pixels; 0 = off)", s.filterSize);
  if (!inOpenClosed(s.normalSupport, 0.0, 2.0)) fail("normalSupport", "in (0, 2]", s.normalSupport);
  if (!inOpenClosed(s.positionSupport, 0.0, 4.0))
    fail("positionSupport", "in (0, 4] (units of R)", s.positionSupport);
  if (!inOpenClosed(s.aoSupport, 0.0, 1.0)) fail("aoSupport", "in (0, 1]", s.aoSupport);
  if (s.bakeRays < 1 || s.bakeRays > 4096) fail("bakeRays", "in 1..4096", s.bakeRays);
  if (s.view != HybridView::None && s.view != HybridView::AO && s.view != HybridView::Normals &&
      s.view != HybridView::Depth && s.view != HybridView::Voxels)
    fail("view", "none, ao, normals, depth or voxels", static_cast<int>(s.view));
}

}  // namespace aokit
