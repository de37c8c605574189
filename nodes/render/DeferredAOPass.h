#pragma once
// DeferredAOPass: the pipeline every screen-resolution AO family shares, as a VTK render pass.
//
//   1. plan: the frame's context (R and falloff from the family's settings, else the scene's, else a
//      tenth of the visible bounds' diagonal: render/FrameContext.h) and the family's plan (its
//      configuration and programs, render/DeferredPlan.h); every program is built here, once per
//      frame, before anything is drawn.
//   2. G-buffer (GBufferPass, lean layout: colour with AO flags in alpha, packed normal, depth;
//      optional guard band, instance ids and baked AO). Positions are reconstructed from depth.
//      With the ranks of a parallel renderer (SetRankExchange), composited across them by depth.
//   3. the family's AO stage(s), at 1/downsample of the screen resolution: RenderAO() writes
//      occlusion (or 1 - W per colour and 1 - O with ambient transfer) into the AO target and the
//      view z of each target texel's pixel into the z target, and may filter the result further.
//   4. upsampling to full resolution: the 2x2 bilinear taps around each pixel, each dropped when
//      its depth is not within a tolerance of the pixel's (inside the combine), or the separable
//      joint bilateral filter over an m x m window (render/DeferredUpsampler.h).
//   5. combine: colour * (1 - AO) where the prop receives AO, depth written back; or the AO alone
//      (ReadAO), or a debug view (AO, normals, depth). In a multisampled window VTK draws the
//      opaque geometry once more into the window's samples, and the combine multiplies them by
//      1 - AO (the G-buffer is single-sampled), so edges stay anti-aliased. With baked AO on, each pixel's per-vertex
//      baked AO (G-buffer) is combined first: AO = 1 - (1 - baked)(1 - AO).
//   6. the family's overlay, when its plan asks for one (its own debug views).
//   7. what VTK draws after opaque geometry (render/AfterOpaque.h): translucent geometry (depth
//      peeling when the renderer asks), FXAA, volumes, overlays, over the combined frame and its
//      depth. The G-buffer draws lights and opaque geometry only, unless SetDelegatePass gave it
//      a delegate of the user's, which then draws everything it draws into the G-buffer.
// During hardware selection (pickers, vtkHardwareSelector) it draws what VTK draws without a pass.
// Each stage is timed with GPU timestamps when timing is on (GetStageTimes()): "gbuffer", the
// family's stages, "upsample" (separable mode), "combine". GL state is restored by scoped guards;
// a program that fails to compile is reported once and the frame is shown without AO.
//
// A family derives from it and implements CommonSettings(), Plan() and RenderAO(); its stages are
// FullScreenStage programs whose sources contain "//AOKIT::DeferredCommon" (the G-buffer helpers of
// shaders/DeferredCommon.glsl), bound with DeferredFrame::bindCommon().
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <vtkNew.h>
#include <vtkOpenGLRenderPass.h>
#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

#include "render/DeferredFrame.h"
#include "render/FullScreenStage.h"
#include "render/GBufferPass.h"
#include "render/StageTimer.h"

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

namespace aokit {

class AfterOpaque;
class RankExchange;

class DeferredAOPass : public vtkOpenGLRenderPass {
 public:
  vtkTypeMacro(DeferredAOPass, vtkOpenGLRenderPass);

  // The pass that draws the scene into the G-buffer (by default VTK's render steps with lights and
  // opaque geometry; the rest is drawn after the combine). A vtkRenderStepsPass of the user's is
  // split the same way (its lights and opaque passes into the G-buffer, its translucent, volumetric
  // and overlay passes after); any other delegate draws all it draws into the G-buffer.
  void SetDelegatePass(vtkRenderPass* delegate);
  vtkRenderPass* GetDelegatePass() const;

  // The AO radius and falloff used when the settings leave them open (an AOScene's, usually).
  // Radius 0 (the default): a tenth of the diagonal of the renderer's visible bounds.
  void SetSceneRadius(double r);
  double GetSceneRadius() const { return SceneRadius; }
  void SetSceneFalloff(Falloff f);
  // Converge while the view rests (render/AOAccumulator.h): the AO becomes the running mean of up
  // to N still frames, each with new samples; the renderer's next Render() continues the sum, and
  // any change of camera, props or settings starts it again. 0 (default): the settings' own
  // `accumulate` (1 = off). Logs an error and keeps the value on N outside 0..256.
  void SetAccumulate(int n);
  int GetAccumulate() const { return Accumulate; }
  // Frames in the mean the last frame of `renderer` showed (default: the renderer drawn last); 0
  // when accumulation is off or before the first frame.
  int GetAccumulatedFrames(vtkRenderer* renderer = nullptr) const;
  Falloff GetSceneFalloff() const { return SceneFalloff; }
  // The last frame's resolved context (R, falloff).
  const FrameContext& GetFrameContext() const { return Frame.context; }

  void Render(const vtkRenderState* s) final;
  void ReleaseGraphicsResources(vtkWindow* w) final;

  // The last frame's AO of `renderer` (default: the renderer drawn last) at full resolution of its
  // viewport (upsampled like the combine stage), one float per pixel in [0, 1], bottom row first;
  // with ambient transfer, 1 - W averaged over colours; 0 where the prop receives no AO. Renders
  // into a temporary target that is released afterwards. The context must be current. Returns false
  // before that renderer's first frame. `covered` (optional): 1 where a surface was drawn.
  bool ReadAO(vtkOpenGLRenderWindow* renWin, std::vector<float>& ao, std::vector<std::uint8_t>* covered = nullptr,
              vtkRenderer* renderer = nullptr);

  // GPU bytes of everything it holds: G-buffers and AO targets of every renderer, the family's own.
  std::size_t MemoryBytes() const;
  // The G-buffer of `renderer` (default: the renderer drawn last); null before its first frame.
  GBufferPass* GetGBufferPass(vtkRenderer* renderer = nullptr) const;

  // A parallel renderer's ranks (parallel/RankExchange.h; ParaView under mpiexec): with more than
  // one, the G-buffer is composited across them before the AO stages and the world-space families
  // cast from every rank's geometry, so the AO is the one-process AO. Every rank must draw the same
  // frames. Accumulation is off then (a rank's props may change alone). Null (default): one process.
  void SetRankExchange(std::shared_ptr<RankExchange> ranks);
  RankExchange* GetRankExchange() const { return Ranks.get(); }
  // Bytes this rank contributed to the last frame's exchanges (G-buffer and casters), 0 alone.
  std::size_t GetExchangedBytes() const { return Frame.context.exchangedBytes; }

  // GPU stage times of the last frame (timing off by default).
  void SetStageTiming(StageTiming mode) { Timer.setMode(mode); }
  const StageTimes& GetStageTimes() { return Timer.results(); }

 protected:
  DeferredAOPass();
  ~DeferredAOPass() override;

  // The family's shared settings (radius, falloff, scale, upsampling, view).
  virtual const DeferredSettings& CommonSettings() const = 0;
  // Before the plan, with the renderer: a family that finds its inputs in the renderer's props (the
  // field family's own occluders) does so here, and may hold the context's radius.
  virtual void PrepareFrame(vtkRenderer*, FrameContext&) {}
  // Whether the radius is the user's (settings or SetSceneRadius), not taken from the visible bounds.
  bool RadiusIsGiven() const { return CommonSettings().radius > 0.0 || SceneRadius > 0.0; }
  // This frame's plan: plan.config arrives filled from CommonSettings() and the context; the
  // family adds what it needs (channels, guard band, ids, baked AO) and lists its programs.
  virtual void Plan(const FrameContext& context, DeferredPlan& plan) = 0;
  // Renders this frame's AO into f.aoTarget and f.zTarget (blend and depth test are off) and any
  // further stages; returns the texture holding the final AO at the target size (f.aoTarget, or
  // f.resultTarget when the plan asked for one), or nullptr when a stage failed. A pass may serve
  // several renderers: whatever a frame's AO lives in must be the frame's (the base keeps one set
  // of G-buffer and targets per renderer).
  virtual vtkTextureObject* RenderAO(DeferredFrame& f) = 0;
  // Draws over the combined frame (the renderer's viewport, depth test off) when the plan asked.
  virtual void RenderOverlay(DeferredFrame&) {}
  virtual std::size_t FamilyMemoryBytes() const { return 0; }
  virtual void ReleaseFamily(vtkWindow*) {}
  // For a family's destructor: releases everything in the window the pass last drew in, if that
  // window is still alive (a pass dropped without ReleaseGraphicsResources must not leave GL
  // objects in it; the base's own destructor cannot reach the family's resources).
  void ReleaseOnDestroy();

 private:
  struct View;  // one renderer's G-buffer, targets and last frame
  // What the combine writes. Frame: the lit colour times 1 - AO, and depth; Blend: 1 - AO and
  // depth on covered pixels, blended onto the colour blitted before; Multiply: 1 - AO onto VTK's
  // multisampled frame; AO: the AO alone (ReadAO).
  enum class CombineOutput { Frame, AO, Multiply, Blend };
  View& ViewOf(vtkRenderer* renderer);
  const View* FindView(vtkRenderer* renderer) const;
  const char* Ready(const DeferredPlan& plan, bool multiply, CombineOutput combine);
  bool Multisampled(vtkRenderer* r, const DeferredConfig& c);
  void AllocateTargets(View& v, bool resultTarget);
  void RenderAfterOpaque(const vtkRenderState* s);
  vtkSmartPointer<vtkRenderPass> GBufferDelegate() const;
  std::string CombineDefines(const DeferredConfig& c, CombineOutput output) const;
  // Binds the combine program of that output and its inputs, then calls draw().
  template <class Draw>
  bool Combine(View& v, FullScreenStage& stage, CombineOutput output, Draw&& draw);

  vtkSmartPointer<vtkRenderPass> Delegate;  // null: each G-buffer's vtkRenderStepsPass
  vtkWeakPointer<vtkOpenGLRenderWindow> LastWindow;  // the window of the last frame
  StageTimer Timer;
  DeferredFrame Frame;  // the frame being drawn, or the last
  double SceneRadius = 0.0;
  Falloff SceneFalloff = Falloff::Binary;
  int Accumulate = 0;
  std::shared_ptr<RankExchange> Ranks;
  bool WarnedParallelAccumulate = false;
  std::map<vtkRenderer*, std::unique_ptr<View>> Views;
  View* Current = nullptr;  // the renderer drawn last
  std::unique_ptr<AfterOpaque> After;
  vtkSmartPointer<vtkRenderPass> Selection;  // hardware selection (pickers): VTK's own rendering
  FullScreenStage CombineStage, AOOutputStage, MultiplyStage;
  bool WarnedMultisamples = false;
  std::string ReportedFailure;  // the failure last reported (report once, not every frame)

  DeferredAOPass(const DeferredAOPass&) = delete;
  void operator=(const DeferredAOPass&) = delete;
};

}  // namespace aokit
