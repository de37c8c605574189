#include "voxel/PropRegion.h"

#include <algorithm>
#include <cmath>

#include <vtkCamera.h>
#include <vtkPolyData.h>
#include <vtkProp.h>
#include <vtkRenderer.h>

#include "parallel/RankBounds.h"

#include "render/ActorKeys.h"
#include "voxel/CasterBuffers.h"

namespace aokit {

namespace {

Bounds fromVtk(const double* b) {
  Bounds out;
  if (!b || !(b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5])) return out;  // VTK's "empty" is min > max
  out.min = glm::dvec3(b[0], b[2], b[4]);
  out.max = glm::dvec3(b[1], b[3], b[5]);
  return out;
}

bool sameBounds(const Bounds& a, const Bounds& b) { return a.min == b.min && a.max == b.max; }

Bounds grown(Bounds b, double by) {
  b.min -= glm::dvec3(by);
  b.max += glm::dvec3(by);
  return b;
}

Bounds cut(const Bounds& a, const Bounds& b) {
  Bounds r;
  r.min = glm::max(a.min, b.min);
  r.max = glm::min(a.max, b.max);
  return r;
}

// A parallel view's box (position to the far end of the scene along the view direction, the
// view's width and height across), as world bounds of its eight corners.
Bounds parallelViewBox(const FrameView& v) {
  const glm::dvec3 forward = glm::normalize(v.camera.focalPoint - v.camera.position);
  const glm::dvec3 right = glm::normalize(glm::cross(forward, v.camera.viewUp));
  const glm::dvec3 up = glm::cross(right, forward);
  double far = 0.0;
  for (int c = 0; c < 8; ++c) {
    const glm::dvec3 p((c & 1) ? v.scene.max.x : v.scene.min.x, (c & 2) ? v.scene.max.y : v.scene.min.y,
                       (c & 4) ? v.scene.max.z : v.scene.min.z);
    far = std::max(far, glm::dot(p - v.camera.position, forward));
  }
  Bounds box;
  for (int c = 0; c < 8; ++c)
    box.extend(v.camera.position + ((c & 4) ? far : 0.0) * forward +
               ((c & 1) ? 1.0 : -1.0) * v.parallelScale * v.aspect * right + ((c & 2) ? 1.0 : -1.0) * v.parallelScale * up);
  return box;
}

}  // namespace

bool FrameView::operator==(const FrameView& o) const {
  return camera.position == o.camera.position && camera.focalPoint == o.camera.focalPoint &&
         camera.viewUp == o.camera.viewUp && camera.viewAngleDeg == o.camera.viewAngleDeg && parallel == o.parallel &&
         parallelScale == o.parallelScale && aspect == o.aspect && sameBounds(scene, o.scene);
}

FrameCasters gatherCasters(vtkRenderer* renderer, PropMeshes& meshes, RankExchange* ranks) {
  FrameCasters out;
  for (const PropMesh& m : meshes.collect(renderer, ranks)) {
    out.props.push_back(m.keys);  // the keys the draw carries (static or dynamic)
    out.polys.push_back(m.poly);
    out.matrices.push_back(m.modelToWorld);
    out.bounds.push_back(m.wholeProp ? fromVtk(m.prop->GetBounds()) : fromVtk(m.poly->GetBounds()).transformed(m.modelToWorld));
  }
  return out;
}

FrameView frameView(vtkRenderer* renderer, RankExchange* ranks) {
  FrameView v;
  vtkCamera* cam = renderer->GetActiveCamera();
  double p[3], f[3], u[3];
  cam->GetPosition(p);
  cam->GetFocalPoint(f);
  cam->GetViewUp(u);
  v.camera.position = glm::dvec3(p[0], p[1], p[2]);
  v.camera.focalPoint = glm::dvec3(f[0], f[1], f[2]);
  v.camera.viewUp = glm::dvec3(u[0], u[1], u[2]);
  v.aspect = renderer->GetTiledAspectRatio();
  double angle = cam->GetViewAngle();
  if (cam->GetUseHorizontalViewAngle())  // VTK's angle then spans the width: the vertical one
    angle = 2.0 * glm::degrees(std::atan(std::tan(glm::radians(0.5 * angle)) / v.aspect));
  v.camera.viewAngleDeg = angle;
  v.parallel = cam->GetParallelProjection() != 0;
  v.parallelScale = cam->GetParallelScale();
  double b[6];
  visiblePropBounds(renderer, ranks, b);
  v.scene = fromVtk(b);
  return v;
}

VoxelRegion computePropRegion(const FrameView& v, const std::vector<Bounds>& casters, double R,
                              const HybridSettings& s) {
  validate(s);
  if (!v.scene.valid()) return VoxelRegion{};
  if (!v.parallel || hasFixedRegion(s))
    return computeVoxelRegion(casters, ViewFrustum::covering(v.camera, v.aspect, v.scene), R, s);
  // Parallel view: the casters within R of its box, in a fixed box cut to the budget around the
  // focal point.
  const Bounds reach = grown(parallelViewBox(v), R);
  Bounds box;
  for (const Bounds& b : casters)
    if (b.valid()) box.extend(cut(b, reach));
  if (!box.valid()) return VoxelRegion{};
  box = cut(box, grown(Bounds{v.camera.focalPoint, v.camera.focalPoint}, 0.5 * s.regionBudget * R));
  if (!box.valid()) return VoxelRegion{};
  HybridSettings fixed = s;
  fixed.regionBox = box;
  const double voxel = std::max({box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z}) / s.gridResolution;
  if (!(voxel > 0.0)) return VoxelRegion{};
  for (int a = 0; a < 3; ++a)  // a flat box (a lone plane) needs a voxel of thickness to be valid
    if (!(box.max[a] - box.min[a] > 0.0)) {
      fixed.regionBox.min[a] -= 0.5 * voxel;
      fixed.regionBox.max[a] += 0.5 * voxel;
    }
  return computeVoxelRegion(casters, ViewFrustum::covering(v.camera, v.aspect, v.scene), R, fixed);
}

std::vector<bool> staticFlags(const FrameCasters& casters) {
  std::vector<bool> out(casters.props.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = !propDynamic(casters.props[i]);
  return out;
}

StaticDynamicPlan computePropStaticDynamic(const FrameView& v, const std::vector<Bounds>& casters,
                                           const std::vector<bool>& isStatic, double R, const HybridSettings& s) {
  validate(s);
  if (!v.scene.valid()) return StaticDynamicPlan{};
  const ViewFrustum frustum = ViewFrustum::covering(v.camera, v.aspect, v.scene);
  if (!v.parallel || hasFixedRegion(s)) return planStaticDynamic(casters, isStatic, frustum, R, s);
  const VoxelRegion dyn = computePropRegion(v, dynamicBoundsOnly(casters, isStatic), R, s);
  return planAroundDynamicRegion(casters, isStatic, dyn, grown(parallelViewBox(v), R), frustum, R, s);
}

const StaticDynamicPlan& PlanCache::get(const FrameView& view, const std::vector<Bounds>& bounds,
                                        const std::vector<bool>& isStatic, double R, const HybridSettings& settings) {
  bool same = valid_ && view == view_ && R == radius_ && bounds.size() == bounds_.size() && isStatic == static_;
  for (std::size_t i = 0; same && i < bounds.size(); ++i) same = sameBounds(bounds[i], bounds_[i]);
  if (same) return plan_;
  plan_ = computePropStaticDynamic(view, bounds, isStatic, R, settings);
  view_ = view;
  bounds_ = bounds;
  static_ = isStatic;
  radius_ = R;
  valid_ = true;
  ++recomputed_;
  return plan_;
}

const VoxelRegion& RegionCache::get(const FrameView& view, const std::vector<Bounds>& bounds, double R,
                                    const HybridSettings& settings) {
  bool same = valid_ && view == view_ && R == radius_ && bounds.size() == bounds_.size();
  for (std::size_t i = 0; same && i < bounds.size(); ++i) same = sameBounds(bounds[i], bounds_[i]);
  if (same) return region_;
  region_ = computePropRegion(view, bounds, R, settings);
  view_ = view;
  bounds_ = bounds;
  radius_ = R;
  valid_ = true;
  ++recomputed_;
  return region_;
}

}  // namespace aokit
