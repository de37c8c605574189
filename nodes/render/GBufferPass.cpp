#include "render/GBufferPass.h"

#include <vtkObjectFactory.h>
#include <vtkOpenGLError.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLQuadHelper.h>
#include <vtkOpenGLRenderUtilities.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkRenderState.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "GBufferCopyFS.h"
#include "GBufferOutputFS.h"
#include "GBufferOutputLeanFS.h"

namespace aokit {

vtkStandardNewMacro(GBufferPass);

GBufferPass::GBufferPass() { Delegate = vtkSmartPointer<vtkRenderStepsPass>::New(); }

GBufferPass::~GBufferPass() { delete CopyQuad; }

void GBufferPass::SetDelegatePass(vtkRenderPass* delegate) {
  Delegate = delegate;
  Modified();
}

void GBufferPass::SetLean(bool on) {
  if (on == Lean) return;
  Lean = on;
  // The targets and the mappers' shaders change: drop the targets, and Modified() makes VTK
  // rebuild the shaders (it keys them on this pass's MTime).
  ColorTexture = PositionTexture = NormalTexture = DepthTexture = nullptr;
  Framebuffer = nullptr;
  Width = Height = 0;
  LayoutTime.Modified();
  Modified();
}

namespace {
vtkSmartPointer<vtkTextureObject> makeTarget(vtkOpenGLRenderWindow* renWin, int internalFormat, int format,
                                              int dataType, int components, int vtkType, int w, int h) {
  auto t = vtkSmartPointer<vtkTextureObject>::New();
  t->SetContext(renWin);
  t->SetInternalFormat(internalFormat);
  t->SetFormat(format);
  t->SetDataType(dataType);
  // Nearest: AO passes must not blend positions across silhouettes.
  t->SetMinificationFilter(vtkTextureObject::Nearest);
  t->SetMagnificationFilter(vtkTextureObject::Nearest);
  t->SetWrapS(vtkTextureObject::ClampToEdge);
  t->SetWrapT(vtkTextureObject::ClampToEdge);
  t->Allocate2D(w, h, components, vtkType);
  return t;
}
}  // namespace

void GBufferPass::Allocate(vtkOpenGLRenderWindow* renWin, int w, int h) {
  if (!Framebuffer) {
    ColorTexture = makeTarget(renWin, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, VTK_UNSIGNED_CHAR, w, h);
    if (Lean) {
      NormalTexture = makeTarget(renWin, GL_RGB10_A2, GL_RGBA, GL_UNSIGNED_BYTE, 4, VTK_UNSIGNED_CHAR, w, h);
    } else {
      PositionTexture = makeTarget(renWin, GL_RGBA32F, GL_RGBA, GL_FLOAT, 4, VTK_FLOAT, w, h);
      NormalTexture = makeTarget(renWin, GL_RGBA32F, GL_RGBA, GL_FLOAT, 4, VTK_FLOAT, w, h);
    }
    DepthTexture = vtkSmartPointer<vtkTextureObject>::New();
    DepthTexture->SetContext(renWin);
    DepthTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    DepthTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    DepthTexture->AllocateDepth(w, h, vtkTextureObject::Float32);
    Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    Framebuffer->SetContext(renWin);
  } else if (w != Width || h != Height) {
    ColorTexture->Resize(w, h);
    if (PositionTexture) PositionTexture->Resize(w, h);
    NormalTexture->Resize(w, h);
    DepthTexture->Resize(w, h);
  }
  Width = w;
  Height = h;
}

void GBufferPass::Render(const vtkRenderState* s) {
  vtkOpenGLClearErrorMacro();
  NumberOfRenderedProps = 0;
  if (!Delegate) {
    vtkWarningMacro("GBufferPass has no delegate");
    return;
  }
  vtkRenderer* r = s->GetRenderer();
  auto* renWin = static_cast<vtkOpenGLRenderWindow*>(r->GetRenderWindow());
  vtkOpenGLState* state = renWin->GetState();
  vtkOpenGLState::ScopedglEnableDisable blendSaver(state, GL_BLEND);
  vtkOpenGLState::ScopedglEnableDisable depthSaver(state, GL_DEPTH_TEST);

  int x, y, w, h;
  r->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  Allocate(renWin, w, h);

  PreRender(s);
  Framebuffer->SaveCurrentBindingsAndBuffers();
  Framebuffer->Bind();
  Framebuffer->AddColorAttachment(0, ColorTexture);
  if (Lean) {
    Framebuffer->AddColorAttachment(1, NormalTexture);
  } else {
    Framebuffer->AddColorAttachment(1, PositionTexture);
    Framebuffer->AddColorAttachment(2, NormalTexture);
  }
  Framebuffer->AddDepthAttachment(DepthTexture);
  Framebuffer->ActivateDrawBuffers(Attachments());
  Framebuffer->StartNonOrtho(w, h);
  // Background must read as "not covered" in the position/normal targets whatever VTK clears to.
  const float zero[4] = {0, 0, 0, 0};
  for (int i = 1; i < Attachments(); ++i) glClearBufferfv(GL_COLOR, i, zero);
  Delegate->Render(s);
  NumberOfRenderedProps += Delegate->GetNumberOfRenderedProps();
  Framebuffer->UnBind();
  Framebuffer->RestorePreviousBindingsAndBuffers();
  PostRender(s);

  if (CopyToOutput) {
    state->vtkglViewport(x, y, w, h);
    state->vtkglScissor(x, y, w, h);
    CopyToFramebuffer(renWin);
  }
  vtkOpenGLCheckErrorMacro("failed after GBufferPass::Render");
}

void GBufferPass::CopyToFramebuffer(vtkOpenGLRenderWindow* renWin) {
  if (!CopyQuad) {
    CopyQuad = new vtkOpenGLQuadHelper(renWin, vtkOpenGLRenderUtilities::GetFullScreenQuadVertexShader().c_str(),
                                       GBufferCopyFS, "");
  } else {
    renWin->GetShaderCache()->ReadyShaderProgram(CopyQuad->Program);
  }
  if (!CopyQuad->Program || !CopyQuad->Program->GetCompiled()) {
    vtkErrorMacro("could not build the G-buffer copy shader");
    return;
  }
  vtkOpenGLState* state = renWin->GetState();
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  ColorTexture->Activate();
  DepthTexture->Activate();
  CopyQuad->Program->SetUniformi("texColor", ColorTexture->GetTextureUnit());
  CopyQuad->Program->SetUniformi("texDepth", DepthTexture->GetTextureUnit());
  CopyQuad->Render();
  ColorTexture->Deactivate();
  DepthTexture->Deactivate();
  state->vtkglDepthFunc(GL_LEQUAL);
}

bool GBufferPass::PreReplaceShaderValues(std::string&, std::string&, std::string& fs, vtkAbstractMapper* mapper,
                                         vtkProp*) {
  if (vtkOpenGLPolyDataMapper::SafeDownCast(mapper))
    vtkShaderProgram::Substitute(fs, "//VTK::Light::Impl", "//VTK::Light::Impl\n  //AOKIT::GBuffer::Impl\n", false);
  return true;
}

bool GBufferPass::PostReplaceShaderValues(std::string&, std::string&, std::string& fs, vtkAbstractMapper* mapper,
                                          vtkProp*) {
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper)) return true;
  if (fs.find("vertexVC") != std::string::npos && fs.find("normalVCVSOutput") != std::string::npos) {
    vtkShaderProgram::Substitute(fs, "//AOKIT::GBuffer::Impl", Lean ? GBufferOutputLeanFS : GBufferOutputFS, false);
  } else {
    // Without the varyings (no lighting, no normals) the surface cannot be described: leave it
    // out of the G-buffer rather than write garbage.
    vtkShaderProgram::Substitute(fs, "//AOKIT::GBuffer::Impl",
                                 Lean ? "gl_FragData[1] = vec4(0.0);\n"
                                      : "gl_FragData[1] = vec4(0.0);\n  gl_FragData[2] = vec4(0.0);\n",
                                 false);
  }
  return true;
}

bool GBufferPass::SetShaderParameters(vtkShaderProgram*, vtkAbstractMapper* mapper, vtkProp*,
                                      vtkOpenGLVertexArrayObject*) {
  Framebuffer->ActivateDrawBuffers(vtkOpenGLPolyDataMapper::SafeDownCast(mapper) ? Attachments() : 1);
  return true;
}

bool GBufferPass::ReadBack(std::vector<float>& positionsVC, std::vector<float>& normalsVC) {
  if (!Framebuffer || Width == 0 || Lean) return false;
  const std::size_t n = static_cast<std::size_t>(Width) * Height * 4;
  positionsVC.resize(n);
  normalsVC.resize(n);
  Framebuffer->SaveCurrentBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  Framebuffer->Bind(GL_READ_FRAMEBUFFER);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_COLOR_ATTACHMENT1);
  glReadPixels(0, 0, Width, Height, GL_RGBA, GL_FLOAT, positionsVC.data());
  glReadBuffer(GL_COLOR_ATTACHMENT2);
  glReadPixels(0, 0, Width, Height, GL_RGBA, GL_FLOAT, normalsVC.data());
  Framebuffer->UnBind(GL_READ_FRAMEBUFFER);
  Framebuffer->RestorePreviousBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  return true;
}

std::size_t GBufferPass::MemoryBytes() const {
  // Colour RGBA8 and depth 32F, then position + normal (2 x RGBA32F) or the packed normal.
  return static_cast<std::size_t>(Width) * Height * (4 + 4 + (Lean ? 4 : 16 + 16));
}

void GBufferPass::ReleaseGraphicsResources(vtkWindow* w) {
  Superclass::ReleaseGraphicsResources(w);
  if (Delegate) Delegate->ReleaseGraphicsResources(w);
  delete CopyQuad;
  CopyQuad = nullptr;
  ColorTexture = PositionTexture = NormalTexture = DepthTexture = nullptr;
  Framebuffer = nullptr;
  Width = Height = 0;
}

}  // namespace aokit
