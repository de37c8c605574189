#pragma once
// Which colour attachments a draw writes. vtkOpenGLState caches the draw buffers and compares only
// the first `count` entries, so going from two buffers to one (same first entry) never reaches GL:
// the second attachment stays active and takes whatever the next shader leaves in its second
// output. Every pass goes through this instead of vtkOpenGLFramebufferObject::ActivateDrawBuffers.
class vtkOpenGLFramebufferObject;

namespace aokit {

// Draw buffers 0..count-1 of the bound framebuffer `fbo` (GL_NONE first, so the change reaches GL).
void activateDrawBuffers(vtkOpenGLFramebufferObject* fbo, int count);

}  // namespace aokit
