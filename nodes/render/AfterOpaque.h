#pragma once
// What VTK draws after opaque geometry, drawn over a deferred pass's combined frame in VTK's order:
// translucent geometry (order-independent transparency, or depth peeling when the renderer asks
// for it: vtkRenderer::DeviceRenderTranslucentPolygonalGeometry), FXAA when the renderer uses it,
// volumes (unless depth peeling took them), overlays. So AO is computed from and applied to opaque
// geometry only: glass does not darken what is seen through it, and volumes keep their own depth
// test against the combined frame's depth. The G-buffer then draws opaque geometry only
// (opaqueSteps()).
#include <vtkRenderPass.h>  // held by vtkSmartPointer
#include <vtkSmartPointer.h>

class vtkOpenGLFXAAFilter;
class vtkOverlayPass;
class vtkRenderState;
class vtkRenderStepsPass;
class vtkVolumetricPass;
class vtkWindow;

namespace aokit {

// The G-buffer's delegate: VTK's render steps with lights and opaque geometry only; those of
// `steps` (a user's vtkRenderStepsPass) when given.
vtkSmartPointer<vtkRenderPass> opaqueSteps(vtkRenderStepsPass* steps = nullptr);

class AfterOpaque {
 public:
  AfterOpaque();
  ~AfterOpaque();
  AfterOpaque(const AfterOpaque&) = delete;
  AfterOpaque& operator=(const AfterOpaque&) = delete;

  // Into the framebuffer and viewport of `s` (the window's), whose depth is the opaque geometry's.
  // With `steps` (a user's vtkRenderStepsPass), its translucent, volumetric and overlay passes draw
  // (a vtkDualDepthPeelingPass among them, say) instead of the renderer's own choice.
  void render(const vtkRenderState* s, vtkRenderStepsPass* steps = nullptr);
  void release(vtkWindow* w);

 private:
  vtkSmartPointer<vtkVolumetricPass> volumes_;
  vtkSmartPointer<vtkOverlayPass> overlays_;
  vtkSmartPointer<vtkOpenGLFXAAFilter> fxaa_;
};

}  // namespace aokit
