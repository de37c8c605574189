#include "render/FullScreenStage.h"

#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLQuadHelper.h>
#include <vtkOpenGLRenderUtilities.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

#include "DeferredCommon.h"
#include "render/DrawBuffers.h"

namespace aokit {

FullScreenStage::FullScreenStage(std::string name, const char* fragmentSource)
    : name_(std::move(name)), source_(fragmentSource) {}

FullScreenStage::~FullScreenStage() { release(); }

std::string FullScreenStage::fragmentSource(const std::string& defines) const {
  std::string fs = source_;
  vtkShaderProgram::Substitute(fs, "//AOKIT::Defines", defines, false);
  vtkShaderProgram::Substitute(fs, "//AOKIT::DeferredCommon", DeferredCommon, false);
  return fs;
}

vtkShaderProgram* FullScreenStage::ready(vtkOpenGLRenderWindow* renWin, const std::string& defines) {
  if (quad_ && defines == defines_) {
    if (failed_) return nullptr;  // do not retry (and re-log) a known failure every frame
    renWin->GetShaderCache()->ReadyShaderProgram(quad_->Program);
    return quad_->Program;
  }
  release();
  defines_ = defines;
  quad_ = new vtkOpenGLQuadHelper(renWin, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(),
                                  fragmentSource(defines).c_str(), "");
  failed_ = !quad_->Program || !quad_->Program->GetCompiled();
  return failed_ ? nullptr : quad_->Program;
}

vtkShaderProgram* FullScreenStage::use(vtkOpenGLRenderWindow* renWin) {
  if (!quad_ || failed_) return nullptr;
  renWin->GetShaderCache()->ReadyShaderProgram(quad_->Program);
  return quad_->Program;
}

void FullScreenStage::render() {
  if (quad_ && !failed_) quad_->Render();
}

void FullScreenStage::renderInto(vtkOpenGLFramebufferObject* fbo, std::initializer_list<vtkTextureObject*> targets) {
  vtkOpenGLState* state = fbo->GetContext()->GetState();
  state->PushFramebufferBindings();
  fbo->Bind();
  unsigned i = 0;
  for (vtkTextureObject* t : targets) fbo->AddColorAttachment(i++, t);
  activateDrawBuffers(fbo, static_cast<int>(i));
  vtkTextureObject* first = *targets.begin();
  fbo->Start(first->GetWidth(), first->GetHeight());  // Start, unlike StartNonOrtho, sets the viewport
  render();
  fbo->RemoveColorAttachments(i);
  state->PopFramebufferBindings();
}

// The program belongs to the window's shader cache (shared by source, released with the window,
// which may already have freed it): only the quad's own objects are ours.
void FullScreenStage::release(vtkWindow*) {
  delete quad_;
  quad_ = nullptr;
  failed_ = false;
  defines_.clear();
}

}  // namespace aokit
