#pragma once
// HybridPass: Hybrid Ambient Occlusion (Reinbothe, Boubekeur, Alexa 2009, seed 004) as a VTK render
// pass, for the scene-graph technique (HybridTechnique) and for plain VTK alike:
//
//   vtkNew<aokit::HybridPass> ao;
//   aokit::HybridSettings s;   // defaults below
//   ao->SetSettings(s);        // throws std::invalid_argument (one line) on bad settings
//   ao->SetSceneRadius(1.5);   // AO radius R when the settings leave it 0; 0 = a tenth of the
//   renderer->SetPass(ao);     //   diagonal of the visible bounds
//
// It is a DeferredAOPass (render/DeferredAOPass.h); its stages, timed as "voxelize" and "march":
//   voxelize: the region of interest (PropRegion.h: casters within R of the view frustum, cut to
//      the budget), then the casters' triangles into the bit-packed grid on the GPU
//      (GpuVoxelizer.h: compute shaders, ThreeAxis by default, solid parity fill);
//   march: at half (or quarter) resolution, each texel's surface point ray-marched through the
//      grid (shaders/HybridMarchFS.glsl, exactly nodes/voxel/HybridMarch.cpp's estimator);
// then the base's separable joint bilateral upsampling over m = filterSize pixels with the
// settings' normal, position and AO supports ("upsample"), and the combine.
// Every frame is voxelized anew (the method is for dynamic scenes); the region is recomputed only
// when the camera, a caster's bounds or the radius changed, and a caster's triangles are uploaded
// again only when its polydata changes. Casters are the renderer's visible props that cast AO
// (ActorKeys.h) and show vtkPolyData (CasterBuffers.h). The voxel view (settings.view) ray-casts
// the grid from the camera at full resolution.
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
// Defaults (HybridSettings): grid 256 on the region's longest side, ThreeAxis, solid fill, 64 MiB
// budget, 32 rays x 8 steps with span tests, normal offset 2 voxels, half resolution, m = 16.
#include <memory>
#include <string>

#include "render/DeferredAOPass.h"
#include "voxel/CasterBuffers.h"
#include "voxel/CpuVoxelizer.h"
#include "voxel/HybridMarch.h"
#include "voxel/HybridSettings.h"
#include "voxel/PropRegion.h"

namespace aokit {

class FullScreenStage;
class GpuVoxelizer;
class VoxelGrid;

class HybridPass : public DeferredAOPass {
 public:
  static HybridPass* New();
  vtkTypeMacro(HybridPass, DeferredAOPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Throws std::invalid_argument (one line) on bad settings and keeps the previous ones.
  void SetSettings(const HybridSettings& s);
  const HybridSettings& GetSettings() const { return Settings; }
  // The AO radius and falloff used when the settings leave them open (AOScene's, usually).
  void SetSceneRadius(double r);
  void SetSceneFalloff(Falloff f);

  // What the last frame used: its region (empty: no caster near the view, AO 0), the march's
  // constants, the casters voxelized (static mode: dynamic and static grids together).
  const VoxelRegion& GetRegion() const { return Region; }
  const HybridMarchConstants& GetConstants() const { return Constants; }
  std::size_t GetVoxelizedCasters() const { return VoxelizedCasters; }
  std::size_t GetVoxelizedStaticCasters() const { return VoxelizedStatic; }
  const std::vector<Bounds>& GetDynamicZones() const { return Zones; }  // static mode
  int GetRegionComputations() const { return Regions.recomputed() + Plans.recomputed(); }
  std::size_t GetCasterUploads() const { return Buffers.uploads(); }
  // The last frame's grid, read back word for word (context current); false before one.
  bool ReadGrid(vtkOpenGLRenderWindow* renWin, VoxelGrid& out);

 protected:
  HybridPass();
  ~HybridPass() override;

  DeferredConfig Configure(vtkRenderer* renderer) override;
  const char* ReadyFamily(const DeferredFrame& f) override;
  vtkTextureObject* RenderAO(DeferredFrame& f) override;
  std::size_t FamilyMemoryBytes() const override;
  void ReleaseFamily(vtkWindow* w) override;

 private:
  double ResolvedRadius(vtkRenderer* renderer) const;
  std::string MarchDefines() const;
  void Voxelize(DeferredFrame& f);
  void VoxelizeStaticDynamic(DeferredFrame& f, const FrameCasters& casters);
  void BindGrid(vtkShaderProgram* p, const DeferredFrame& f);
  void UnbindGrid();
  bool StaticMode() const { return Settings.staticBake; }

  HybridSettings Settings;
  double SceneRadius = 0.0;
  Falloff SceneFalloff = Falloff::Binary;
  double Radius = 1.0;  // resolved this frame
  VoxelRegion Region;
  std::vector<Bounds> Zones;
  HybridMarchConstants Constants;
  std::size_t VoxelizedCasters = 0, VoxelizedStatic = 0;
  bool HasGrid = false;

  RegionCache Regions;
  PlanCache Plans;
  CasterBuffers Buffers;
  std::unique_ptr<GpuVoxelizer> Voxelizer;
  std::unique_ptr<GpuVoxelizer> StaticVoxelizer;  // static mode: the static casters meeting the region
  std::unique_ptr<FullScreenStage> MarchStage, VoxelViewStage;
  vtkSmartPointer<vtkTextureObject> EmptyGrid;  // bound when no grid exists (a sampler needs a texture)

  HybridPass(const HybridPass&) = delete;
  void operator=(const HybridPass&) = delete;
};

// Rays the march may trace in one pass: llvmpipe ends a shader invocation's loops after 65535
// iterations in all (a GPU has no such limit, but long invocations risk its watchdog), so heavy
// settings march in several passes. All rays when there is no grid.
int raysPerMarchPass(const HybridMarchConstants& c, bool hasGrid);

// The voxelizer a VoxelizingFrame setting stands for.
VoxelizeMethod voxelizeMethodFor(VoxelizingFrame frame);

}  // namespace aokit
