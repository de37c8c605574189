#pragma once
// The region of interest of one frame of a VTK renderer (issue 9 items 2 and 3): the caster props
// (render/ActorKeys.h casterProps: plain VTK props count as casters) that show vtkPolyData, their
// world bounds, the view frustum of the active camera, and computeVoxelRegion (VoxelRegion.h) over
// them: the same function, on the same numbers, as the CPU oracle computeHybridAOCpu, which takes
// them from the scene graph. A parallel camera has no frustum: its region is the casters within R
// of its view box, cut to regionBudget R around the focal point.
// RegionCache keeps the last region and recomputes it only when its inputs changed (camera,
// aspect, any caster's bounds, R; its owner clears it when the settings change): techniques live
// across frames.
#include <vector>

#include "core/Bounds.h"
#include "core/Camera.h"
#include "voxel/HybridSettings.h"
#include "voxel/StaticDynamic.h"
#include "render/PropMeshes.h"
#include "voxel/VoxelRegion.h"

class vtkPolyData;
class vtkProp;
class vtkRenderer;

namespace aokit {

struct FrameCasters {
  std::vector<vtkProp*> props;        // the prop whose keys each caster mesh carries (render/PropMeshes.h)
  std::vector<vtkPolyData*> polys;    // the meshes (pipelines brought up to date)
  std::vector<glm::dmat4> matrices;   // model to world
  std::vector<Bounds> bounds;         // their world bounds
};

// Every mesh the renderer's casting props draw (composite blocks, glyph instances, assembly parts
// included: render/PropMeshes.h, which warns once about props it cannot read).
// With the ranks of a parallel renderer: every rank's meshes (parallel/RankMeshes.h).
FrameCasters gatherCasters(vtkRenderer* renderer, PropMeshes& meshes, RankExchange* ranks = nullptr);

// The renderer's view as the region needs it.
struct FrameView {
  Camera camera;                // position, focal point, view up, vertical view angle
  bool parallel = false;
  double parallelScale = 1.0;   // half the view's height, world units (parallel only)
  double aspect = 1.0;          // width / height of the renderer's viewport
  Bounds scene;                 // bounds of every visible prop (the frustum's depth)
  bool operator==(const FrameView& o) const;
};

// Its scene box is every rank's with the ranks of a parallel renderer.
FrameView frameView(vtkRenderer* renderer, RankExchange* ranks = nullptr);

// The region (settings validated first; std::invalid_argument on bad ones).
VoxelRegion computePropRegion(const FrameView& view, const std::vector<Bounds>& casterBounds, double R,
                              const HybridSettings& settings);

// The static/dynamic plan of the frame (StaticDynamic.h): isStatic per caster (ActorKeys.h
// propDynamic false). A parallel view's dynamic region is computePropRegion's, cut to its box.
StaticDynamicPlan computePropStaticDynamic(const FrameView& view, const std::vector<Bounds>& casterBounds,
                                           const std::vector<bool>& isStatic, double R, const HybridSettings& settings);

// The static flags of the frame's casters.
std::vector<bool> staticFlags(const FrameCasters& casters);

class RegionCache {
 public:
  // The region for these inputs; recomputed only when they differ from the last call's (the
  // settings are not compared: clear() when they change).
  const VoxelRegion& get(const FrameView& view, const std::vector<Bounds>& casterBounds, double R,
                         const HybridSettings& settings);
  int recomputed() const { return recomputed_; }  // how many times get() recomputed (tests)
  void clear() { valid_ = false; }

 private:
  bool valid_ = false;
  FrameView view_;
  std::vector<Bounds> bounds_;
  double radius_ = 0.0;
  VoxelRegion region_;
  int recomputed_ = 0;
};

// As RegionCache, for the static/dynamic plan (also recomputed when a caster's static flag changes).
class PlanCache {
 public:
  const StaticDynamicPlan& get(const FrameView& view, const std::vector<Bounds>& casterBounds,
                               const std::vector<bool>& isStatic, double R, const HybridSettings& settings);
  int recomputed() const { return recomputed_; }
  void clear() { valid_ = false; }

 private:
  bool valid_ = false;
  FrameView view_;
  std::vector<Bounds> bounds_;
  std::vector<bool> static_;
  double radius_ = 0.0;
  StaticDynamicPlan plan_;
  int recomputed_ = 0;
};

}  // namespace aokit
