#pragma once
// DeferredAOPass: the pipeline every screen-resolution AO family shares, as a VTK render pass.
//
//   1. G-buffer (GBufferPass, lean layout: colour with AO flags in alpha, packed normal, depth;
//      optional guard band and instance ids). Positions are reconstructed from depth.
//   2. the family's AO stage(s), at 1/downsample of the screen resolution: RenderAO() writes
//      occlusion (or 1 - W per colour and 1 - O with ambient transfer) into the AO target and the
//      view z of each target texel's pixel into the z target, and may filter the result further.
//   3. upsampling to full resolution: the 2x2 bilinear taps around each pixel, each dropped when
//      its depth is not within a tolerance of the pixel's (one pass, inside the combine), or a
//      separable joint bilateral filter over an m x m window (Reinbothe et al., Hybrid AO,
//      eqs. 5-8: Wendland domain kernel; position, normal and AO range kernels): a horizontal
//      pass to a (screen width x target height) target, the vertical taps inside the combine;
//      exactly voxel/BilateralUpsample.h's contract, whose CPU version is its oracle.
//   4. combine: colour * (1 - AO) where the prop receives AO, depth written back; or the AO alone
//      (ReadAO), or a debug view. With baked AO on, each pixel's per-vertex baked AO (G-buffer) is
//      combined first: AO = 1 - (1 - baked)(1 - AO).
// Each stage is timed with GPU timestamps when timing is on (GetStageTimes()): "gbuffer", the
// family's stages, "upsample" (separable mode), "combine". GL state is restored by scoped guards;
// a program that fails to compile is reported once and the frame is shown without AO.
//
// A family derives from it and implements Configure(), ReadyFamily() and RenderAO(); its stages
// are FullScreenStage programs whose sources contain "//AOKIT::DeferredCommon" (the G-buffer
// helpers of shaders/DeferredCommon.glsl), bound with DeferredFrame::bindCommon().
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <vtkNew.h>
#include <vtkOpenGLRenderPass.h>
#include <vtkSmartPointer.h>

#include "render/DeferredConfig.h"
#include "render/GBufferPass.h"
#include "render/StageTimer.h"

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkOpenGLState;
class vtkShaderProgram;
class vtkTextureObject;

namespace aokit {

class FullScreenStage;

// What a family's RenderAO() gets: the frame's G-buffer, targets and helpers.
struct DeferredFrame {
  vtkRenderer* renderer = nullptr;
  vtkOpenGLRenderWindow* renWin = nullptr;
  vtkOpenGLState* state = nullptr;
  GBufferPass* gbuffer = nullptr;
  vtkOpenGLFramebufferObject* fbo = nullptr;  // for FullScreenStage::renderInto
  DeferredConfig config;
  int screenWidth = 0, screenHeight = 0, targetWidth = 0, targetHeight = 0;
  vtkTextureObject* aoTarget = nullptr;  // aoChannels floats per texel at the target size
  vtkTextureObject* zTarget = nullptr;   // R32F: view z of the texel's pixel, +1 on background
  StageTimer* timer = nullptr;
  float clip[3][4] = {};                 // rows 0, 1, 3 of the G-buffer's view -> clip matrix
  float depthToZ[4] = {};                // window depth -> view z (DeferredCommon.glsl)
  float viewToWorld[16] = {};            // column-major, for GLSL mat4
  double worldToView[16] = {};           // VTK's model-view matrix, row-major
  bool hasNonCasters = false;            // some visible prop is drawn but casts no AO

  // Sets the uniforms and samplers of DeferredCommon.glsl on p (the G-buffer textures are active
  // for the whole AO phase of the frame).
  void bindCommon(vtkShaderProgram* p) const;
  // Marks the end of a stage on the timer (no-op when timing is off).
  void mark(const char* stage) const;
};

class DeferredAOPass : public vtkOpenGLRenderPass {
 public:
  vtkTypeMacro(DeferredAOPass, vtkOpenGLRenderPass);

  // The pass that draws the scene into the G-buffer (vtkRenderStepsPass by default).
  void SetDelegatePass(vtkRenderPass* delegate);
  vtkRenderPass* GetDelegatePass() const;

  void Render(const vtkRenderState* s) override;
  void ReleaseGraphicsResources(vtkWindow* w) override;

  // The last frame's AO at full resolution (upsampled like the combine stage), one float per
  // pixel in [0, 1], bottom row first; with ambient transfer, 1 - W averaged over colours; 0 where
  // the prop receives no AO. Renders into a temporary target that is released afterwards. The
  // context must be current. Returns false before the first frame. `covered` (optional): 1 where
  // a surface was drawn.
  bool ReadAO(vtkOpenGLRenderWindow* renWin, std::vector<float>& ao, std::vector<std::uint8_t>* covered = nullptr);

  // GPU bytes of everything it holds: G-buffer, AO targets, the family's own.
  std::size_t MemoryBytes() const;
  GBufferPass* GetGBufferPass() const { return GBuffer; }

  // GPU stage times of the last frame (timing off by default).
  void SetStageTiming(bool on) { Timer.setEnabled(on); }
  const StageTimes& GetStageTimes() { return Timer.results(); }

 protected:
  DeferredAOPass();
  ~DeferredAOPass() override;

  // Called first in every frame: what this frame needs (cheap; the base reallocates on change).
  virtual DeferredConfig Configure(vtkRenderer* renderer) = 0;
  // Builds every program of the family for this frame (f.renWin, f.config and f.hasNonCasters are
  // set; the rest is not yet); returns the name of a stage that does not compile, or nullptr.
  virtual const char* ReadyFamily(const DeferredFrame& f) = 0;
  // Renders this frame's AO into f.aoTarget and f.zTarget (blend and depth test are off) and any
  // further stages; returns the texture holding the final AO at the target size (f.aoTarget or one
  // of the family's), or nullptr when a stage failed.
  virtual vtkTextureObject* RenderAO(DeferredFrame& f) = 0;
  virtual std::size_t FamilyMemoryBytes() const { return 0; }
  virtual void ReleaseFamily(vtkWindow*) {}

 private:
  void AllocateTargets(vtkOpenGLRenderWindow* renWin);
  std::string CombineDefines(bool outputAO) const;
  bool RenderUpsample(vtkTextureObject* ao);
  // Binds the combine program (frame or AO-output variant) and its inputs, then calls draw().
  template <class Draw>
  bool Combine(FullScreenStage& stage, bool outputAO, Draw&& draw);

  vtkNew<GBufferPass> GBuffer;
  StageTimer Timer;
  DeferredFrame Frame;
  vtkSmartPointer<vtkOpenGLFramebufferObject> Framebuffer;
  // Separable upsampling: the horizontal pass's AO (RowTarget) and the guide of its rows
  // (RowGuide: view normal and z of the pixel each row texel stands for), so that the vertical
  // pass reads one texel per tap for its range weights, not the G-buffer's normal and depth.
  vtkSmartPointer<vtkTextureObject> AOTarget, ZTarget, RowTarget, RowGuide;
  vtkTextureObject* Result = nullptr;                              // the family's final AO
  int AllocatedChannels = 0;
  std::unique_ptr<FullScreenStage> UpsampleStage, CombineStage, AOOutputStage;
  bool HasFrame = false;
  std::string ReportedFailure;  // the failure last reported (report once, not every frame)

  DeferredAOPass(const DeferredAOPass&) = delete;
  void operator=(const DeferredAOPass&) = delete;
};

}  // namespace aokit
