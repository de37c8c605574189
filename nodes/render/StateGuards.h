#pragma once
#include <vtkOpenGLState.h>
#include <vtk_glew.h>

namespace aokit {

// Saves what the stages change and restores it when the pass returns.
struct StateGuards {
  vtkOpenGLState::ScopedglEnableDisable blend, depthTest, scissorTest;
  vtkOpenGLState::ScopedglViewport viewport;
  vtkOpenGLState::ScopedglScissor scissor;
  vtkOpenGLState::ScopedglDepthFunc depthFunc;
  vtkOpenGLState::ScopedglDepthMask depthMask;
  explicit StateGuards(vtkOpenGLState* s)
      : blend(s, GL_BLEND), depthTest(s, GL_DEPTH_TEST), scissorTest(s, GL_SCISSOR_TEST), viewport(s), scissor(s),
        depthFunc(s), depthMask(s) {}
};

}  // namespace aokit
