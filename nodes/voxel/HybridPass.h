#pragma once
// HybridPass: Hybrid Ambient Occlusion (Reinbothe, Boubekeur, Alexa 2009, seed 004) as a VTK render
// pass, for the scene-graph technique (HybridTechnique) and for plain VTK alike:
//
//   vtkNew<aokit::HybridPass> ao;
//   aokit::HybridSettings s;   // defaults below; hybridSchema() has every key, range and help
//   ao->SetSettings(s);        // throws std::invalid_argument (one line) on bad settings
//   ao->SetSceneRadius(1.5);   // AO radius R when the settings leave it 0; 0 = a tenth of the
//   renderer->SetPass(ao);     //   diagonal of the visible bounds
//
// It is a DeferredAOPass (render/DeferredAOPass.h); its stages, timed as "voxelize" and "march":
//   voxelize (HybridVoxelStage.h): the region of interest (PropRegion.h: casters within R of the
//      view frustum, cut to the budget), then the casters' triangles into the bit-packed grid on
//      the GPU (GpuVoxelizer.h: compute shaders, ThreeAxis by default, solid parity fill);
//   march: at half (or quarter) resolution, each texel's surface point ray-marched through the
//      grid (shaders/HybridMarchFS.glsl, exactly nodes/voxel/HybridMarch.cpp's estimator);
// then the base's separable joint bilateral upsampling over the settings' window m with their
// normal, position and AO supports ("upsample"), and the combine.
// Every frame is voxelized anew (the method is for dynamic scenes); the region is recomputed only
// when the camera, a caster's bounds or the radius changed, and a caster's triangles are uploaded
// again only when its polydata changes. Casters are the renderer's visible props that cast AO
// (ActorKeys.h) and show vtkPolyData (CasterBuffers.h). The voxel view (view=voxels) ray-casts
// the grid from the camera over the frame (an overlay after the combine).
//
// Static plus dynamic (settings.staticBake; StaticDynamic.h): props marked static (ActorKeys.h
// propDynamic false) carry per-vertex AO baked from the static casters (StaticProps.h: the
// technique bakes in prepare(), plain VTK calls bakeStaticProps), the G-buffer carries it and the
// combine applies it (DeferredConfig::bakedAO). The region is the dynamic casters' bounds grown by
// R; the dynamic casters go into one grid, the static ones meeting the region into a second; a
// static receiver (G-buffer flag AO_FLAG_DYNAMIC clear) marches the dynamic grid only, and not at
// all outside the zones of the dynamic casters (each one's bounds grown by R: its occlusion is
// all baked there), a dynamic one marches both.
//
// Defaults (HybridSettings): grid 256 on the region's longest side, DominantAxis, solid fill,
// 64 MiB budget, 16 rays of at least 8 steps (at most one voxel each) with span tests, normal
// offset 1 voxel, the falloff from the surface point, half resolution, m = 16.
#include <memory>
#include <string>

#include "render/DeferredAOPass.h"
#include "voxel/HybridSettings.h"
#include "voxel/HybridVoxelStage.h"

namespace aokit {

class VoxelGrid;

class HybridPass : public DeferredAOPass {
 public:
  static HybridPass* New();
  vtkTypeMacro(HybridPass, DeferredAOPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Throws std::invalid_argument (one line) on bad settings and keeps the previous ones.
  void SetSettings(const HybridSettings& s);
  const HybridSettings& GetSettings() const { return Settings; }

  // What the last frame used: its region (empty: no caster near the view, AO 0), the march's
  // constants, the casters voxelized (static mode: dynamic and static grids together).
  const VoxelRegion& GetRegion() const { return Voxels.region(); }
  const HybridMarchConstants& GetConstants() const { return Voxels.constants(); }
  std::size_t GetVoxelizedCasters() const { return Voxels.voxelizedCasters(); }
  std::size_t GetVoxelizedStaticCasters() const { return Voxels.voxelizedStaticCasters(); }
  const std::vector<Bounds>& GetDynamicZones() const { return Voxels.zones(); }  // static mode
  int GetRegionComputations() const { return Voxels.regionComputations(); }
  std::size_t GetCasterUploads() const { return Voxels.casterUploads(); }
  // The last frame's grid, read back word for word (context current); false before one.
  bool ReadGrid(vtkOpenGLRenderWindow* renWin, VoxelGrid& out) { return Voxels.readGrid(renWin, out); }

 protected:
  HybridPass();
  ~HybridPass() override;

  const DeferredSettings& CommonSettings() const override { return Settings.common; }
  void Plan(const FrameContext& context, DeferredPlan& plan) override;
  vtkTextureObject* RenderAO(DeferredFrame& f) override;
  void RenderOverlay(DeferredFrame& f) override;
  std::size_t FamilyMemoryBytes() const override { return Voxels.memoryBytes(); }
  void ReleaseFamily(vtkWindow* w) override;

 private:
  std::string MarchDefines(const FrameContext& context) const;

  HybridSettings Settings;
  HybridVoxelStage Voxels;
  std::unique_ptr<FullScreenStage> MarchStage, VoxelViewStage;

  HybridPass(const HybridPass&) = delete;
  void operator=(const HybridPass&) = delete;
};

// Rays the march may trace in one pass: llvmpipe ends a shader invocation's loops after 65535
// iterations in all (a GPU has no such limit, but long invocations risk its watchdog), so heavy
// settings march in several passes. All rays when there is no grid.
int raysPerMarchPass(const HybridMarchConstants& c, bool hasGrid);

}  // namespace aokit
