#pragma once
// FieldPass: ambient occlusion from baked occluder fields (seeds 000, 001, 002) as a VTK render
// pass, by deferred evaluation over the occluders (seed 000's Algorithm 3).
//
// As a drop-in, it finds its occluders itself (PropOccluders.h):
//   vtkNew<aokit::FieldPass> ao;
//   ao->SetSceneRadius(R);        // bakes are for R: without one, R comes from the visible bounds
//   renderer->SetPass(ao);        //   of the first frame and is held (a new R would re-bake)
// Each distinct polydata is baked once (through the bake cache, keyed by content), the actors'
// matrices are followed each frame without a bake, a polydata whose data changed is baked again,
// and bakes report VTK StartEvent, ProgressEvent (a double in [0, 1]) and EndEvent on the pass.
// Or with fields baked offline (the scene-graph technique, FieldTechnique.h, does this):
//   ao->SetFields(fields);        // distinct baked fields (BakedField.h): cube ones and one grid kind
//   ao->SetOccluders(occluders);  // each: field index, occluder -> world (a similarity), instance id
//                                 // moving an occluder: SetOccluders again, no re-bake
//
// It is a DeferredAOPass (render/DeferredAOPass.h: G-buffer with instance ids, upsampling, combine,
// read-back, stage timers). Its "fields" stage is seed 000's Algorithm 3, one draw per occluder:
//   start:     occlusion 0 and the view z at every AO-target texel (FieldPassStartFS.glsl);
//   cull:      the receivers' depth range per tile of 16 x 16 AO-target texels (FieldCull.h),
//              read back, so that each occluder is drawn only over the tiles whose receivers its
//              influence sphere reaches (FieldScreenRect.h; occluders off screen cost nothing);
//   occluders: for each occluder, cube fields first, draws scissored to those tiles, whose
//              fragments leave at once where there is no receiver, the pixel is the occluder's
//              own, or the point is outside the sphere (beyond it A is exactly 0); the others
//              evaluate the field (cube: Algorithm 1; grid: the 6- or 4-term lookup) and combine:
//              multiply by blending, cones through an image read and written in draw order
//              (FieldPassOccluderFS.glsl); cones then take a resolve pass to the AO target.
// So the work follows the pixels each occluder can reach, not the number of occluders.
// Field data lives in buffer textures filtered in the shader (FieldGpuData.h, FieldTextures.h), so
// any number of fields of any resolution cost exactly their bytes; the look-up tables are
// GL_LINEAR textures. The slice debug view is drawn over the frame (FieldSliceView.h).
// The CPU specification of every pixel is FieldSceneEval.h.
#include <memory>
#include <string>
#include <vector>

#include "fields/FieldCull.h"
#include "fields/FieldGpuData.h"
#include "fields/FieldSettings.h"
#include "fields/FieldSliceView.h"
#include "fields/FieldTextures.h"
#include "fields/PropOccluders.h"
#include "render/DeferredAOPass.h"

namespace aokit {

class FieldPass : public DeferredAOPass {
 public:
  static FieldPass* New();
  vtkTypeMacro(FieldPass, DeferredAOPass);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // Throws std::invalid_argument (one line) on bad settings and keeps the previous ones. The pass
  // uses the common, evaluation and slice settings; the bake settings are its technique's.
  void SetSettings(const FieldSettings& s);
  const FieldSettings& GetSettings() const { return Settings; }
  // The distinct fields, uploaded at the next frame; ends the drop-in mode. Throws
  // std::invalid_argument when they are of different kinds or hold no data (FieldGpuData.h).
  void SetFields(std::vector<std::shared_ptr<const BakedField>> fields);
  // Where each occluder is; uploaded at the next frame (a few floats per occluder); ends the
  // drop-in mode. Throws std::invalid_argument when one names a field out of range.
  void SetOccluders(std::vector<FieldOccluder> occluders);
  // Drop-in mode: occluders found in the renderer's props each frame (on until SetFields or
  // SetOccluders).
  void SetFindOccluders(bool on);
  bool GetFindOccluders() const { return FindOccluders; }
  // The drop-in mode's last re-plan: fields baked, read from the cache, kept.
  const FieldPrepareReport& GetFoundReport() const;
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

 protected:
  FieldPass();
  ~FieldPass() override;

  const DeferredSettings& CommonSettings() const override { return Settings.common; }
  void PrepareFrame(vtkRenderer* renderer, FrameContext& context) override;
  void Plan(const FrameContext& context, DeferredPlan& plan) override;
  vtkTextureObject* RenderAO(DeferredFrame& f) override;
  void RenderOverlay(DeferredFrame& f) override;
  std::size_t FamilyMemoryBytes() const override;
  void ReleaseFamily(vtkWindow* w) override;

 private:
  void UseFields(std::vector<std::shared_ptr<const BakedField>> fields);
  void UseOccluders(std::vector<FieldOccluder> occluders);
  bool RenderOccluders(DeferredFrame& f);
  bool AttachTargets(DeferredFrame& f);
  void DrawStart(DeferredFrame& f, vtkShaderProgram* p);
  bool DrawOccluders(DeferredFrame& f, const TileDepths& tiles, bool cubes);
  bool ResolveCones(DeferredFrame& f);

  FieldSettings Settings;
  bool FindOccluders = true;
  std::unique_ptr<PropOccluders> Found;  // the drop-in mode's
  double HeldRadius = 0.0;               // the drop-in mode's R when none is given
  FieldConstants Constants;  // this frame's
  bool BakedAO = false;
  std::vector<std::shared_ptr<const BakedField>> Fields;
  std::vector<FieldOccluder> Occluders;
  FieldGpuData FieldData;
  OccluderGpuData OccluderData;
  FieldTextures Textures;
  FieldCull Cull;
  FieldSliceView Slice;

  std::string OccluderSource;  // FieldPassOccluderFS with FieldPassEval.glsl in
  std::unique_ptr<FullScreenStage> StartStage, CubeStage, GridStage, ResolveStage;
  vtkSmartPointer<vtkTextureObject> StateTarget;   // cone mode: the running cones
  vtkSmartPointer<vtkTextureObject> DepthStencil;  // AO-target size: receivers' depth and instance ids
  long long DrawnTexels = 0;  // last frame: texels inside the occluders' scissor rectangles (tests, stats)
  int DrawnOccluders = 0, DrawCalls = 0;

  FieldPass(const FieldPass&) = delete;
  void operator=(const FieldPass&) = delete;
};

}  // namespace aokit
