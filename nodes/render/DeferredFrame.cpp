#include "render/DeferredFrame.h"

#include <glm/glm.hpp>
#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

#include "render/GBufferPass.h"
#include "render/StageTimer.h"

namespace aokit {

void DeferredFrame::setView(vtkRenderer* r, GBufferPass* g) {
  gbuffer = g;
  screenWidth = g->GetScreenWidth();
  screenHeight = g->GetScreenHeight();
  vtkMatrix4x4* proj = g->GetProjection();
  for (int j = 0; j < 4; ++j) {
    clip[0][j] = static_cast<float>(proj->GetElement(0, j));
    clip[1][j] = static_cast<float>(proj->GetElement(1, j));
    clip[2][j] = static_cast<float>(proj->GetElement(3, j));
  }
  // ndc z = (A z + B) / (C z + D): enough to turn window depth back into view z (both projections).
  depthToZ[0] = static_cast<float>(proj->GetElement(2, 2));
  depthToZ[1] = static_cast<float>(proj->GetElement(2, 3));
  depthToZ[2] = static_cast<float>(proj->GetElement(3, 2));
  depthToZ[3] = static_cast<float>(proj->GetElement(3, 3));
  vtkMatrix4x4* view = r->GetActiveCamera()->GetModelViewTransformMatrix();
  glm::dmat4 toView;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      worldToView[i * 4 + j] = view->GetElement(i, j);
      toView[j][i] = view->GetElement(i, j);
    }
  const glm::dmat4 toWorld = glm::inverse(toView);
  for (int c = 0; c < 4; ++c)
    for (int rr = 0; rr < 4; ++rr) viewToWorld[c * 4 + rr] = static_cast<float>(toWorld[c][rr]);
}

void DeferredFrame::bindCommon(vtkShaderProgram* p) const {
  p->SetUniformi("aoDepth", gbuffer->GetDepthTexture()->GetTextureUnit());
  p->SetUniformi("aoNormal", gbuffer->GetNormalTexture()->GetTextureUnit());
  p->SetUniformi("aoColor", gbuffer->GetColorTexture()->GetTextureUnit());
  p->SetUniformi("aoFlagsTex", gbuffer->GetFlagsTexture()->GetTextureUnit());
  const int guard[2] = {gbuffer->GetGuardX(), gbuffer->GetGuardY()};
  const int screen[2] = {screenWidth, screenHeight};
  p->SetUniform2i("aoGuard", guard);
  p->SetUniform2i("aoScreen", screen);
  p->SetUniform4f("aoClipX", clip[0]);
  p->SetUniform4f("aoClipY", clip[1]);
  p->SetUniform4f("aoClipW", clip[2]);
  p->SetUniform4f("aoDepthToZ", depthToZ);
  p->SetUniformMatrix4x4("aoViewToWorld", const_cast<float*>(viewToWorld));
}

void DeferredFrame::mark(const char* stage) const {
  if (timer) timer->mark(stage);
}

DeferredConfig makeDeferredConfig(const DeferredSettings& s, const FrameContext& frame) {
  DeferredConfig c;
  c.downsample = static_cast<int>(s.scale);
  c.radius = frame.radius;
  c.upsample = s.upsample;
  c.view = s.view;
  c.facetNormals = s.normal == AONormal::Facet;
  c.accumulate = s.accumulate;
  return c;
}

}  // namespace aokit
