#include "render/DrawBuffers.h"

#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtk_glew.h>

namespace aokit {

void activateDrawBuffers(vtkOpenGLFramebufferObject* fbo, int count) {
  unsigned none = GL_NONE;
  fbo->GetContext()->GetState()->vtkglDrawBuffers(1, &none);
  fbo->ActivateDrawBuffers(static_cast<unsigned>(count));
}

}  // namespace aokit
