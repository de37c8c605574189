#include "screen/ScreenQuadStage.h"

#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLQuadHelper.h>
#include <vtkOpenGLRenderUtilities.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

namespace aokit {

ScreenQuadStage::ScreenQuadStage(std::string name, const char* fragmentSource)
    : name_(std::move(name)), source_(fragmentSource) {}

ScreenQuadStage::~ScreenQuadStage() { release(); }

std::string ScreenQuadStage::fragmentSource(const std::string& defines) const {
  std::string fs = source_;
  vtkShaderProgram::Substitute(fs, "//AOKIT::Obscurance::Defines", defines, false);
  return fs;
}

vtkShaderProgram* ScreenQuadStage::ready(vtkOpenGLRenderWindow* renWin, const std::string& defines) {
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

void ScreenQuadStage::render() {
  if (quad_ && !failed_) quad_->Render();
}

void ScreenQuadStage::renderInto(vtkOpenGLFramebufferObject* fbo, vtkTextureObject* target,
                                 vtkTextureObject* second) {
  vtkOpenGLState* state = fbo->GetContext()->GetState();
  state->PushFramebufferBindings();
  fbo->Bind();
  fbo->AddColorAttachment(0, target);
  if (second) fbo->AddColorAttachment(1, second);
  fbo->ActivateDrawBuffers(second ? 2 : 1);
  fbo->Start(target->GetWidth(), target->GetHeight());  // Start, unlike StartNonOrtho, sets the viewport
  render();
  fbo->RemoveColorAttachments(second ? 2 : 1);
  state->PopFramebufferBindings();
}

void ScreenQuadStage::release() {
  delete quad_;
  quad_ = nullptr;
  failed_ = false;
  defines_.clear();
}

}  // namespace aokit
