#include "screen/ObscuranceFilter.h"

#include <vtkOpenGLRenderWindow.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

#include "ObscurancePassFilterFS.h"

namespace aokit {

ObscuranceFilter::ObscuranceFilter() : stage_("filter", ObscurancePassFilterFS) {}

bool ObscuranceFilter::ready(vtkOpenGLRenderWindow* renWin, const ObscuranceConstants& c) {
  return stage_.ready(renWin, c.defines()) != nullptr;
}

bool ObscuranceFilter::run(vtkOpenGLRenderWindow* renWin, vtkOpenGLFramebufferObject* fbo, vtkTextureObject* raw,
                           vtkTextureObject* viewZ, vtkTextureObject* out, const ObscuranceConstants& c) {
  vtkShaderProgram* p = stage_.ready(renWin, c.defines());  // a bind when already built for c
  if (!p) return false;
  raw->Activate();
  viewZ->Activate();
  p->SetUniformi("obsRaw", raw->GetTextureUnit());
  p->SetUniformi("obsZ", viewZ->GetTextureUnit());
  p->SetUniformf("obsFilterTolerance", c.filterTolerance);
  stage_.renderInto(fbo, {out});
  viewZ->Deactivate();
  raw->Deactivate();
  return true;
}

}  // namespace aokit
