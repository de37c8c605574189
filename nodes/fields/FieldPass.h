#pragma once
// FieldPass: ambient occlusion from baked occluder fields (seeds 000, 001, 002) as a VTK render
// pass, by deferred evaluation over the occluders (seed 000's Algorithm 3).
//
//   vtkNew<aokit::FieldPass> ao;
//   ao->SetFields(fields);        // distinct baked fields (BakedField.h), all of one kind
//   ao->SetOccluders(occluders);  // each: field index, occluder -> world (a similarity), instance id
//   renderer->SetPass(ao);        // moving an occluder: SetOccluders again, no re-bake
//
// It is a DeferredAOPass (render/DeferredAOPass.h: G-buffer with instance ids, upsampling, combine,
// read-back, stage timers). Its "fields" stage is seed 000's Algorithm 3, one draw per occluder:
//   start:     occlusion 0 and the view z at every AO-target texel (FieldPassStartFS.glsl);
//   cull:      the receivers' depth range per tile of 16 x 16 AO-target texels (FieldPassBoundsFS),
//              read back, so that each occluder is drawn only over the tiles whose receivers its
//              influence sphere reaches (FieldScreenRect.h; occluders off screen cost nothing);
//   occluders: for each occluder, cube fields first, draws scissored to those tiles, whose
//              fragments leave at once where there is no receiver, the pixel is the occluder's
//              own, or the point is outside the sphere (beyond it A is exactly 0); the others
//              evaluate the field (cube: Algorithm 1; grid: the 6- or 4-term lookup) and combine:
//              multiply by blending, cones through an image read and written in draw order
//              (FieldPassOccluderFS.glsl); cones then take a resolve pass to the AO target.
// So the work follows the pixels each occluder can reach, not the number of occluders.
// Field data lives in buffer textures filtered in the shader (FieldGpuData.h), so any number of
// fields of any resolution cost exactly their bytes; the look-up tables are GL_LINEAR textures.
// The slice debug view adds a pass after the combine (FieldPassSliceFS.glsl).
// The CPU specification of every pixel is FieldSceneEval.h.
#include <memory>
#include <string>
#include <vector>

#include "fields/FieldGpuData.h"
#include "fields/FieldPassSettings.h"
#include "fields/FieldScreenRect.h"
#include "render/DeferredAOPass.h"

namespace aokit {

class FullScreenStage;

class FieldPass : public DeferredAOPass {
 public:
  static FieldPass* New();
  vtkTypeMacro(FieldPass, DeferredAOPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Throws std::invalid_argument (one line) on bad settings and keeps the previous ones.
  void SetSettings(const FieldPassSettings& s);
  const FieldPassSettings& GetSettings() const { return Settings; }
  // The distinct fields, uploaded at the next frame. Throws std::invalid_argument when they are of
  // different kinds or hold no data (FieldGpuData.h).
  void SetFields(std::vector<std::shared_ptr<const BakedField>> fields);
  // Where each occluder is; uploaded at the next frame (a few floats per occluder). Throws
  // std::invalid_argument when one names a field out of range.
  void SetOccluders(std::vector<FieldOccluder> occluders);
  // The AO radius R (world units): upsampling kernels and the depth debug view only.
  void SetSceneRadius(double r);
  // Combine the per-vertex AO baked into the props (render/BakedAO.h: the occluders'
  // self-occlusion) with the fields': 1 - (1 - baked)(1 - A). Off by default.
  void SetBakedAO(bool on);

  const std::vector<std::shared_ptr<const BakedField>>& GetFields() const { return Fields; }
  const std::vector<FieldOccluder>& GetOccluders() const { return Occluders; }
  // Exact bytes of the field data (what each field's kind and resolution imply).
  std::size_t FieldBytes() const { return FieldData.fieldBytes; }
  // The last frame's occluder draws (those with a rectangle on screen) and the AO-target texels
  // their rectangles cover: the work of the fields stage.
  int GetDrawnOccluders() const { return DrawnOccluders; }
  long long GetDrawnTexels() const { return DrawnTexels; }
  int GetDrawCalls() const { return DrawCalls; }

  void Render(const vtkRenderState* s) override;

 protected:
  FieldPass();
  ~FieldPass() override;

  DeferredConfig Configure(vtkRenderer* renderer) override;
  const char* ReadyFamily(const DeferredFrame& f) override;
  vtkTextureObject* RenderAO(DeferredFrame& f) override;
  std::size_t FamilyMemoryBytes() const override;
  void ReleaseFamily(vtkWindow* w) override;

 private:
  int Mode() const;  // FIELD_MODE: 0 multiply, 1 cones, 2 count
  std::string Defines(int cubes, int grid) const;
  bool Upload(vtkOpenGLRenderWindow* renWin);  // false: too large for this GL (reported)
  void BindFieldData(vtkShaderProgram* p) const;
  bool RenderOccluders(DeferredFrame& f);
  bool ReadTileDepths(DeferredFrame& f, TileDepths& tiles);
  void RenderSlice(const vtkRenderState* s);

  FieldPassSettings Settings;
  double SceneRadius = 1.0;
  bool BakedAO = false;
  std::vector<std::shared_ptr<const BakedField>> Fields;
  std::vector<FieldOccluder> Occluders;
  FieldGpuData FieldData;
  OccluderGpuData OccluderData;
  bool FieldsDirty = true, OccludersDirty = true;

  // Field data and tables (buffer and look-up textures), the running cones (cone mode).
  vtkSmartPointer<vtkTextureObject> Texels4, Texels3, FieldInts, FieldFloats, OccluderFloats, OccluderInts;
  vtkSmartPointer<vtkTextureObject> CapTable, HorizonTable, ClipTable, MergeTable;
  vtkSmartPointer<vtkTextureObject> StateTarget;
  vtkSmartPointer<vtkTextureObject> DepthStencil;  // AO-target size: receivers' depth and instance ids
  std::size_t UploadedBytes = 0;  // of the buffer textures
  std::string EvalSource, OccluderSource, SliceSource;  // stage sources with FieldPassEval.glsl in
  std::unique_ptr<FullScreenStage> BoundsStage, StartStage, CubeStage, GridStage, ResolveStage, SliceStage;
  vtkSmartPointer<vtkTextureObject> BoundsTarget;  // per culling tile: the receivers' view-depth range
  long long DrawnTexels = 0;  // last frame: texels inside the occluders' scissor rectangles (tests, stats)
  int DrawnOccluders = 0, DrawCalls = 0;
  DeferredFrame LastFrame;  // the last frame's G-buffer and matrices, for the slice view

  FieldPass(const FieldPass&) = delete;
  void operator=(const FieldPass&) = delete;
};

}  // namespace aokit
