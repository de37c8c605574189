#include "voxel/VoxelRegion.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/Geometry.h"

namespace aokit {

namespace {

Bounds intersect(const Bounds& a, const Bounds& b) {
  Bounds r;
  r.min = glm::max(a.min, b.min);
  r.max = glm::min(a.max, b.max);
  return r;  // invalid when they miss
}

Bounds grown(Bounds b, double by) {
  b.min -= glm::dvec3(by);
  b.max += glm::dvec3(by);
  return b;
}

double longestSide(const Bounds& b) {
  if (!b.valid()) return 0.0;
  const glm::dvec3 s = b.max - b.min;
  return std::max({s.x, s.y, s.z});
}

// Union of the kept casters' parts that lie within R of the frustum's bounding box.
Bounds regionFor(const std::vector<Bounds>& casters, const std::vector<std::size_t>& kept, const ViewFrustum& f,
                 double R) {
  const Bounds reach = grown(f.bounds(), R);
  Bounds box;
  for (std::size_t i : kept) box.extend(intersect(casters[i], reach));
  return box;
}

}  // namespace

std::vector<Bounds> instanceBounds(const std::vector<GeometryInstance>& instances) {
  std::vector<Bounds> out;
  out.reserve(instances.size());
  for (const auto& inst : instances)
    out.push_back(inst.geometry && inst.geometry->mesh() ? inst.geometry->mesh()->bounds().transformed(inst.world)
                                                         : Bounds{});
  return out;
}

VoxelRegion computeVoxelRegion(const std::vector<Bounds>& casters, const ViewFrustum& frustum, double R,
                               const HybridSettings& s) {
  validate(s);
  if (!(R > 0.0) || !std::isfinite(R)) throw std::invalid_argument("voxel region: R must be positive and finite");
  VoxelRegion out;
  out.coveredDepth = frustum.farDist;
  if (hasFixedRegion(s)) {
    out.box = s.regionBox;
    for (std::size_t i = 0; i < casters.size(); ++i)
      if (casters[i].valid() && intersect(casters[i], s.regionBox).valid()) out.casters.push_back(i);
  } else {
    for (std::size_t i = 0; i < casters.size(); ++i)
      if (casters[i].valid() && frustum.boxWithin(casters[i], R)) out.casters.push_back(i);
    out.box = regionFor(casters, out.casters, frustum, R);
    const double budget = s.regionBudget * R;
    if (out.box.valid() && longestSide(out.box) > budget) {
      // The region grows with the far distance: bisect for the deepest cut that fits.
      double lo = frustum.nearDist, hi = frustum.farDist;
      for (int it = 0; it < 48; ++it) {
        const double mid = 0.5 * (lo + hi);
        (longestSide(regionFor(casters, out.casters, frustum.withFar(mid), R)) <= budget ? lo : hi) = mid;
      }
      out.coveredDepth = lo;
      out.clipped = true;
      out.box = regionFor(casters, out.casters, frustum.withFar(lo), R);
      if (longestSide(out.box) > budget) {  // even the nearest cut is too wide: a cube at the camera
        out.box = intersect(out.box, grown(Bounds{frustum.position, frustum.position}, 0.5 * budget));
        out.coveredDepth = frustum.nearDist;
      }
      // Casters no longer inside the cut region are not drawn.
      std::vector<std::size_t> inside;
      for (std::size_t i : out.casters)
        if (intersect(casters[i], out.box).valid()) inside.push_back(i);
      out.casters.swap(inside);
    }
  }
  if (!out.box.valid() || !(longestSide(out.box) > 0.0) || out.casters.empty()) {
    out.empty = true;
    out.casters.clear();
    return out;
  }
  // A flat region (a lone plane) still needs one voxel of thickness: pad to a voxel.
  const double voxel = longestSide(out.box) / s.gridResolution;
  for (int a = 0; a < 3; ++a)
    if (out.box.max[a] - out.box.min[a] < voxel) {
      const double c = 0.5 * (out.box.min[a] + out.box.max[a]);
      out.box.min[a] = c - 0.5 * voxel;
      out.box.max[a] = c + 0.5 * voxel;
    }
  const glm::dmat3 axes = s.frame == VoxelizingFrame::Rotated ? randomRotation(s.frameSeed) : glm::dmat3(1.0);
  out.frame = s.snapToLattice ? VoxelFrame::onLattice(out.box, s.gridResolution, axes)
                              : VoxelFrame::fitting(out.box, s.gridResolution, axes);
  out.memoryBytes = packedGridBytes(out.frame.dims.x, out.frame.dims.y, out.frame.dims.z);
  out.empty = false;
  return out;
}

}  // namespace aokit
