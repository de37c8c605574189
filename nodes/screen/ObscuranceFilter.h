#pragma once
// The filter stage of ObscurancePass on its own, so that tests can run it on synthetic buffers:
// the 4x4 depth-aware box filter over the interleave period (shaders/ObscurancePassFilterFS.glsl),
// which also resolves W = numerator / denominator in ambient-transfer mode.
#include "screen/ObscuranceSettings.h"
#include "render/FullScreenStage.h"

class vtkOpenGLFramebufferObject;
class vtkOpenGLRenderWindow;
class vtkTextureObject;
class vtkWindow;

namespace aokit {

class ObscuranceFilter {
 public:
  ObscuranceFilter();
  // raw: obscurance stage output (R32F occlusion, or RGBA32F sums with c.transfer); viewZ: R32F view
  // z, +1 on background; out: same size as raw. Blend and depth test must be off (the caller's
  // guards). Returns false when the program does not compile.
  bool run(vtkOpenGLRenderWindow* renWin, vtkOpenGLFramebufferObject* fbo, vtkTextureObject* raw,
           vtkTextureObject* viewZ, vtkTextureObject* out, const ObscuranceConstants& c);
  // Builds the program for these constants without drawing (nullptr on a compile failure).
  bool ready(vtkOpenGLRenderWindow* renWin, const ObscuranceConstants& c);
  void release(vtkWindow* window = nullptr) { stage_.release(window); }
  // The stage itself, for a pass's plan (defines: ObscuranceConstants::defines()).
  FullScreenStage& stage() { return stage_; }

 private:
  FullScreenStage stage_;
};

}  // namespace aokit
