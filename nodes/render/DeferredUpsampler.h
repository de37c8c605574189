#pragma once
// The shared upsampler of the deferred pipeline: the separable joint bilateral filter of Hybrid
// AO's eqs. 5-8 (render/BilateralUpsample.h is its contract and CPU oracle). Its horizontal pass
// (shaders/DeferredUpsampleFS.glsl) filters each AO-target row at full horizontal resolution into
// a row target, beside the guide of those rows (view normal and z of the pixel each row texel
// stands for); the vertical taps run inside the combine (DeferredCombineFS.glsl), which reads the
// rows through bindRows(). With window 0 the combine takes bilinear taps itself and this does
// nothing.
#include <cstddef>
#include <string>

#include <vtkSmartPointer.h>

#include "render/DeferredFrame.h"
#include "render/FullScreenStage.h"

class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace aokit {

class DeferredUpsampler {
 public:
  DeferredUpsampler();
  // Adds the horizontal pass to the plan when the configuration filters (window > 0).
  void plan(DeferredPlan& plan, const std::string& defines);
  // Sizes the row targets for the frame (or drops them when not filtering).
  void allocate(const DeferredFrame& f);
  // The horizontal pass over `ao` (the family's result). False when its program is missing.
  bool run(const DeferredFrame& f, vtkTextureObject* ao);
  // The kernel uniforms shared by both passes.
  static void setKernelUniforms(vtkShaderProgram* p, const DeferredConfig& c);
  // The rows and their guide for the combine's vertical taps (textures must be active).
  void bindRows(vtkShaderProgram* p) const;
  vtkTextureObject* rows() const { return rows_; }
  vtkTextureObject* guide() const { return guide_; }
  std::size_t memoryBytes() const;
  void release(vtkWindow* w);

 private:
  FullScreenStage stage_;
  vtkSmartPointer<vtkTextureObject> rows_, guide_;
};

}  // namespace aokit
