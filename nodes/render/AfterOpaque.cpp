#include "render/AfterOpaque.h"

#include <vtkFXAAOptions.h>
#include <vtkOpenGLFXAAFilter.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLRenderer.h>
#include <vtkOpenGLState.h>
#include <vtkOverlayPass.h>
#include <vtkProp.h>
#include <vtkRenderState.h>
#include <vtkRenderStepsPass.h>
#include <vtkVolumetricPass.h>
#include <vtk_glew.h>

namespace aokit {

vtkSmartPointer<vtkRenderPass> opaqueSteps(vtkRenderStepsPass* from) {
  auto steps = vtkSmartPointer<vtkRenderStepsPass>::New();
  if (from) {
    steps->SetLightsPass(from->GetLightsPass());
    steps->SetOpaquePass(from->GetOpaquePass());
  }
  steps->SetTranslucentPass(nullptr);
  steps->SetVolumetricPass(nullptr);
  steps->SetOverlayPass(nullptr);
  return steps;
}

AfterOpaque::AfterOpaque()
    : volumes_(vtkSmartPointer<vtkVolumetricPass>::New()), overlays_(vtkSmartPointer<vtkOverlayPass>::New()) {}

AfterOpaque::~AfterOpaque() = default;

void AfterOpaque::render(const vtkRenderState* s, vtkRenderStepsPass* steps) {
  auto* r = vtkOpenGLRenderer::SafeDownCast(s->GetRenderer());
  if (!r) return;
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(r->GetRenderWindow())->GetState();
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_LEQUAL);
  state->vtkglDepthMask(GL_TRUE);
  bool translucent = false;
  for (int i = 0; i < s->GetPropArrayCount(); ++i) translucent = translucent || s->GetPropArray()[i]->HasTranslucentPolygonalGeometry();
  if (steps) {
    if (steps->GetTranslucentPass()) steps->GetTranslucentPass()->Render(s);
  } else if (translucent) {
    r->DeviceRenderTranslucentPolygonalGeometry(s->GetFrameBuffer());
  }
  if (r->GetUseFXAA()) {
    if (!fxaa_) fxaa_ = vtkSmartPointer<vtkOpenGLFXAAFilter>::New();
    fxaa_->UpdateConfiguration(r->GetFXAAOptions());
    fxaa_->Execute(r);
  }
  // Depth peeling of volumes draws them with the translucent geometry (dual depth peeling only).
  if (steps) {
    if (steps->GetVolumetricPass()) steps->GetVolumetricPass()->Render(s);
    if (steps->GetOverlayPass()) steps->GetOverlayPass()->Render(s);
    return;
  }
  const bool peeledVolumes = translucent && r->GetUseDepthPeeling() && r->GetUseDepthPeelingForVolumes() &&
                             r->IsDualDepthPeelingSupported();
  if (!peeledVolumes) volumes_->Render(s);
  overlays_->Render(s);
}

void AfterOpaque::release(vtkWindow* w) {
  volumes_->ReleaseGraphicsResources(w);
  overlays_->ReleaseGraphicsResources(w);
  if (fxaa_) fxaa_->ReleaseGraphicsResources();
}

}  // namespace aokit
