#pragma once
// One full-screen fragment program of a render pass: an embedded .glsl source whose
// "//AOKIT::Defines" line receives the shape-changing #defines and whose "//AOKIT::DeferredCommon"
// line (if any) receives shaders/DeferredCommon.glsl, the G-buffer helpers every deferred AO stage
// shares. The program is rebuilt only when the defines change; uniforms are set on it every frame.
#include <initializer_list>
#include <string>

class vtkOpenGLFramebufferObject;
class vtkOpenGLQuadHelper;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

namespace aokit {

class FullScreenStage {
 public:
  FullScreenStage(std::string name, const char* fragmentSource);
  ~FullScreenStage();
  FullScreenStage(const FullScreenStage&) = delete;
  FullScreenStage& operator=(const FullScreenStage&) = delete;

  // Builds (when the defines changed) and binds the program. Returns nullptr when it does not
  // compile or link; VTK's shader cache has then printed the log, and the caller reports the stage.
  vtkShaderProgram* ready(vtkOpenGLRenderWindow* renWin, const std::string& defines);
  // Binds the program the last ready() built (nullptr when it failed or none was built): how a
  // pass's stages draw once its plan has readied them.
  vtkShaderProgram* use(vtkOpenGLRenderWindow* renWin);
  // Draws the quad with the bound program (after ready()) into the current framebuffer.
  void render();
  // Draws it into `targets` (colour attachments 0, 1, ...) through `fbo`, at the first target's
  // size; the previous framebuffer bindings are restored.
  void renderInto(vtkOpenGLFramebufferObject* fbo, std::initializer_list<vtkTextureObject*> targets);
  // Drops the program and vertex arrays. With the window, also the compiled GL program, which
  // VTK's shader cache would otherwise keep for the life of the window (a detached technique must
  // not leave its programs behind).
  void release(vtkWindow* window = nullptr);

  const std::string& name() const { return name_; }
  // The fragment source as compiled for `defines` (tests, debugging).
  std::string fragmentSource(const std::string& defines) const;

 private:
  std::string name_;
  const char* source_;
  std::string defines_;
  vtkOpenGLQuadHelper* quad_ = nullptr;
  bool failed_ = false;
};

}  // namespace aokit
