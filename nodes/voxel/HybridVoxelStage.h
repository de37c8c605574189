#pragma once
// The voxel stage of HybridPass: each frame, the region of interest (PropRegion.h: casters within R
// of the view frustum, cut to the budget; or the static/dynamic plan), then the casters' triangles
// into the bit-packed grid on the GPU (GpuVoxelizer.h), and the grids bound for the march and the
// voxel view. The region is recomputed only when the camera, a caster's bounds or R changed, a
// caster's triangles are uploaded again only when its polydata changes.
#include <cstddef>
#include <memory>
#include <vector>

#include <vtkSmartPointer.h>

#include "render/DeferredPlan.h"
#include "voxel/CasterBuffers.h"
#include "voxel/CpuVoxelizer.h"
#include "voxel/HybridMarch.h"
#include "voxel/PropRegion.h"

class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace aokit {

class GpuVoxelizer;
class VoxelGrid;

class HybridVoxelStage {
 public:
  HybridVoxelStage();
  ~HybridVoxelStage();
  HybridVoxelStage(const HybridVoxelStage&) = delete;
  HybridVoxelStage& operator=(const HybridVoxelStage&) = delete;

  // The voxelizer programs of these settings, for the pass's plan.
  void plan(DeferredPlan& plan, vtkOpenGLRenderWindow* renWin, const HybridSettings& s);
  // Voxelizes this frame's casters; the march's constants for the grid (rays and steps set even
  // when no caster is near the view, AO 0 then). Throws std::invalid_argument when the camera is
  // degenerate or the grid exceeds the context's texture size. With the context's ranks (a
  // parallel renderer), every rank's casters; the bytes sent are added to the context.
  void voxelize(vtkRenderer* renderer, vtkOpenGLRenderWindow* renWin, const HybridSettings& s,
                FrameContext& context);
  // Binds the grid (and static grid, zones) to p's samplers and uniforms; unbind() after drawing.
  void bind(vtkShaderProgram* p, vtkOpenGLRenderWindow* renWin, bool staticMode);
  void unbind(bool staticMode);
  // Drops the cached region (the settings changed).
  void invalidate();

  bool hasGrid() const { return hasGrid_; }
  const HybridMarchConstants& constants() const { return constants_; }
  const VoxelRegion& region() const { return region_; }
  const std::vector<Bounds>& zones() const { return zones_; }
  std::size_t voxelizedCasters() const { return voxelized_; }
  std::size_t voxelizedStaticCasters() const { return voxelizedStatic_; }
  int regionComputations() const { return regions_.recomputed() + plans_.recomputed(); }
  std::size_t casterUploads() const { return buffers_.uploads(); }
  bool readGrid(vtkOpenGLRenderWindow* renWin, VoxelGrid& out);
  std::size_t memoryBytes() const;
  void release(vtkWindow* w);

 private:
  std::vector<CasterDraw> draws(const FrameCasters& casters, const std::vector<std::size_t>& which);
  void voxelizeStaticDynamic(vtkRenderer* renderer, vtkOpenGLRenderWindow* renWin, const HybridSettings& s,
                             const FrameContext& context, const FrameCasters& casters);

  PropMeshes meshes_{"hybrid"};
  RegionCache regions_;
  PlanCache plans_;
  CasterBuffers buffers_;
  std::unique_ptr<GpuVoxelizer> voxelizer_;
  std::unique_ptr<GpuVoxelizer> staticVoxelizer_;  // static mode: the static casters meeting the region
  vtkSmartPointer<vtkTextureObject> emptyGrid_;    // bound when no grid exists (a sampler needs a texture)
  VoxelRegion region_;
  std::vector<Bounds> zones_;
  HybridMarchConstants constants_;
  std::size_t voxelized_ = 0, voxelizedStatic_ = 0;
  bool hasGrid_ = false;
};

// The voxelizer a VoxelizingFrame setting stands for.
VoxelizeMethod voxelizeMethodFor(VoxelizingFrame frame);

}  // namespace aokit
