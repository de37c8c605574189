#include "render/GBufferPass.h"

#include <cmath>
#include <memory>
#include <vector>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLError.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLPolyDataMapper.h>
#include <vtkOpenGLQuadHelper.h>
#include <vtkOpenGLRenderUtilities.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkPropCollection.h>
#include <vtkRenderState.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "GBufferCopyFS.h"
#include "GBufferOutputFS.h"
#include "render/ActorKeys.h"
#include "render/DrawBuffers.h"
#include "render/BakedAO.h"

namespace aokit {

vtkStandardNewMacro(GBufferPass);

GBufferPass::GBufferPass() {
  Delegate = vtkSmartPointer<vtkRenderStepsPass>::New();
  // Mappers keep the shaders they built unless a pass's stage time is newer: a new G-buffer (a
  // reference capture's full layout beside a technique's lean one) must have them rebuilt.
  LayoutTime.Modified();
}

GBufferPass::~GBufferPass() { delete CopyQuad; }

void GBufferPass::SetDelegatePass(vtkRenderPass* delegate) {
  Delegate = delegate;
  Modified();
}

void GBufferPass::DropTargets() {
  // The targets and the mappers' shaders change: drop the targets, and LayoutTime makes VTK
  // rebuild the shaders (GetShaderStageMTime).
  for (auto& t : Targets) t = nullptr;
  DepthTexture = nullptr;
  Framebuffer = nullptr;
  Width = Height = 0;
  LayoutTime.Modified();
  Modified();
}

void GBufferPass::SetLean(bool on) {
  if (on == Options.lean) return;
  Options.lean = on;
  DropTargets();
}

void GBufferPass::SetBakedAO(bool on) {
  if (on == Options.bakedAO) return;
  Options.bakedAO = on;
  DropTargets();
}

void GBufferPass::SetInstanceIds(bool on) {
  if (on == Options.instanceIds) return;
  Options.instanceIds = on;
  DropTargets();
}

void GBufferPass::SetFacetNormals(bool on) {
  if (on == Options.facetNormals) return;
  Options.facetNormals = on;
  DropTargets();  // the layout is the same; the shaders change with LayoutTime
}

void GBufferPass::SetGuardBand(double fraction) {
  if (!(fraction >= 0.0 && fraction <= 1.0)) {
    vtkErrorMacro("guard band must be in 0..1, got " << fraction);
    return;
  }
  if (fraction == Guard) return;
  Guard = fraction;
  Modified();
}

namespace {
// Puts the camera's projection, scaled in x and y, in place for the mappers while alive, and
// restores the camera's explicit-projection state afterwards.
class ScopedGuardProjection {
 public:
  ScopedGuardProjection(vtkCamera* camera, vtkMatrix4x4* scaled)
      : camera_(camera), saved_(camera->GetExplicitProjectionTransformMatrix()),
        savedUse_(camera->GetUseExplicitProjectionTransformMatrix()) {
    camera_->SetExplicitProjectionTransformMatrix(scaled);
    camera_->SetUseExplicitProjectionTransformMatrix(true);
  }
  ~ScopedGuardProjection() {
    camera_->SetExplicitProjectionTransformMatrix(saved_);
    camera_->SetUseExplicitProjectionTransformMatrix(savedUse_);
  }
  ScopedGuardProjection(const ScopedGuardProjection&) = delete;
  ScopedGuardProjection& operator=(const ScopedGuardProjection&) = delete;

 private:
  vtkCamera* camera_;
  vtkSmartPointer<vtkMatrix4x4> saved_;
  bool savedUse_;
};

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
    for (const GBufferTargetFormat& f : gbufferLayout(Options))
      Targets[static_cast<int>(f.target)] =
          makeTarget(renWin, f.internalFormat, f.format, f.type, f.components, f.vtkType, w, h);
    DepthTexture = vtkSmartPointer<vtkTextureObject>::New();
    DepthTexture->SetContext(renWin);
    DepthTexture->SetMinificationFilter(vtkTextureObject::Nearest);
    DepthTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
    DepthTexture->AllocateDepth(w, h, vtkTextureObject::Float32);
    Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    Framebuffer->SetContext(renWin);
  } else if (w != Width || h != Height) {
    for (const GBufferTargetFormat& f : gbufferLayout(Options)) Targets[static_cast<int>(f.target)]->Resize(w, h);
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
  GuardX = static_cast<int>(std::lround(Guard * w));
  GuardY = static_cast<int>(std::lround(Guard * h));
  const int W = w + 2 * GuardX, H = h + 2 * GuardY;
  Allocate(renWin, W, H);
  // The projection of this frame, the one GetKeyMatrices hands the mappers (renderer's aspect);
  // with a guard band, x and y shrink so that the viewport's frustum fills the centre w x h texels:
  // window x' = (ndc sx + 1) W / 2 = (ndc + 1) w / 2 + GuardX.
  vtkCamera* camera = r->GetActiveCamera();
  Parallel = camera->GetParallelProjection() != 0;
  Projection->DeepCopy(camera->GetProjectionTransformMatrix(r->GetTiledAspectRatio(), -1, 1));
  const bool guarded = GuardX > 0 || GuardY > 0;
  const double scale[2] = {static_cast<double>(w) / W, static_cast<double>(h) / H};
  for (int row = 0; row < 2; ++row)
    for (int col = 0; col < 4; ++col) Projection->SetElement(row, col, Projection->GetElement(row, col) * scale[row]);

  // The render state names the FBO: vtkCameraPass then sets the viewport and scissor to the FBO's
  // size at (0, 0) rather than the renderer's tiled size and origin (a renderer in the right half
  // of a window would draw outside its own G-buffer). With a guard band the prop list is every
  // visible prop (the renderer culled against the smaller frustum).
  vtkRenderState fboState(r);
  std::vector<vtkProp*> props;
  if (guarded) {
    vtkPropCollection* all = r->GetViewProps();
    vtkCollectionSimpleIterator it;
    all->InitTraversal(it);
    while (vtkProp* p = all->GetNextProp(it))
      if (p->GetVisibility()) props.push_back(p);
    fboState.SetPropArrayAndCount(props.data(), static_cast<int>(props.size()));
  } else {
    fboState.SetPropArrayAndCount(s->GetPropArray(), s->GetPropArrayCount());
  }
  fboState.SetFrameBuffer(Framebuffer);
  fboState.SetRequiredKeys(s->GetRequiredKeys());
  std::unique_ptr<ScopedGuardProjection> projection;
  if (guarded) projection = std::make_unique<ScopedGuardProjection>(camera, Projection);
  vtkOpenGLState::ScopedglViewport viewportSaver(state);
  vtkOpenGLState::ScopedglScissor scissorSaver(state);

  const vtkRenderState* rs = &fboState;
  PreRender(rs);
  Framebuffer->SaveCurrentBindingsAndBuffers();
  Framebuffer->Bind();
  const std::vector<GBufferTargetFormat> layout = gbufferLayout(Options);
  for (std::size_t i = 0; i < layout.size(); ++i)
    Framebuffer->AddColorAttachment(static_cast<unsigned>(i), Targets[static_cast<int>(layout[i].target)]);
  Framebuffer->AddDepthAttachment(DepthTexture);
  activateDrawBuffers(Framebuffer, Attachments());
  Framebuffer->StartNonOrtho(W, H);
  state->vtkglScissor(0, 0, W, H);  // glClearBuffer obeys the scissor
  // Background must read as "not covered" in the position/normal targets whatever VTK clears to.
  const float zero[4] = {0, 0, 0, 0};
  for (int i = 1; i < Attachments(); ++i) glClearBufferfv(GL_COLOR, i, zero);
  // Only the colour target takes the renderer's background clear (a background alpha of 1 must not
  // mark every pixel covered); polydata mappers switch all targets on for their own draws
  // (SetShaderParameters).
  ActivateDrawBuffers(1);
  Delegate->Render(rs);
  NumberOfRenderedProps += Delegate->GetNumberOfRenderedProps();
  Framebuffer->UnBind();
  Framebuffer->RestorePreviousBindingsAndBuffers();
  projection.reset();
  PostRender(rs);

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
  vtkTextureObject* color = GetColorTexture();
  color->Activate();
  DepthTexture->Activate();
  CopyQuad->Program->SetUniformi("texColor", color->GetTextureUnit());
  CopyQuad->Program->SetUniformi("texDepth", DepthTexture->GetTextureUnit());
  // The viewport's part of the targets: texCoord * scale + offset.
  const float region[4] = {static_cast<float>(GetScreenWidth()) / Width, static_cast<float>(GetScreenHeight()) / Height,
                           static_cast<float>(GuardX) / Width, static_cast<float>(GuardY) / Height};
  CopyQuad->Program->SetUniform4f("texRegion", region);
  CopyQuad->Render();
  color->Deactivate();
  DepthTexture->Deactivate();
  state->vtkglDepthFunc(GL_LEQUAL);
}

void GBufferPass::BlitColorToFramebuffer(vtkOpenGLRenderWindow* renWin, int x, int y) {
  vtkOpenGLState* state = renWin->GetState();
  state->PushReadFramebufferBinding();
  Framebuffer->Bind(GL_READ_FRAMEBUFFER);
  glReadBuffer(GL_COLOR_ATTACHMENT0 + Attachment(GBufferTarget::Color));
  const int w = GetScreenWidth(), h = GetScreenHeight();
  glBlitFramebuffer(GuardX, GuardY, GuardX + w, GuardY + h, x, y, x + w, y + h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  state->PopReadFramebufferBinding();
}

bool GBufferPass::PreReplaceShaderValues(std::string& vs, std::string&, std::string& fs, vtkAbstractMapper* mapper,
                                         vtkProp*) {
  // Markers the mapper leaves alone: our declarations beside the outputs, our code last in main
  // (after texturing, which may rewrite the colour's alpha).
  if (vtkOpenGLPolyDataMapper::SafeDownCast(mapper)) {
    vtkShaderProgram::Substitute(fs, "//VTK::Output::Dec", "//VTK::Output::Dec\n//AOKIT::GBuffer::Dec\n", false);
    vtkShaderProgram::Substitute(fs, "//VTK::Picking::Impl", "//VTK::Picking::Impl\n  //AOKIT::GBuffer::Impl\n", false);
    if (Options.bakedAO) {
      // The baked value rides along as a vertex attribute. Where a mapper has no such array the
      // attribute's current value is undefined (GL leaves it so after array draws): a per-prop
      // uniform scales it to 0 there.
      vtkShaderProgram::Substitute(vs, "//VTK::Normal::Dec",
                                   "//VTK::Normal::Dec\nin vec2 aokitBakedAOMC;\nuniform float aokitBakedScale;\n"
                                   "out vec2 aokitBakedAOVSOutput;",
                                   false);
      vtkShaderProgram::Substitute(vs, "//VTK::Normal::Impl",
                                   "//VTK::Normal::Impl\n  aokitBakedAOVSOutput = aokitBakedScale * aokitBakedAOMC;", false);
    }
  }
  return true;
}

bool GBufferPass::PostReplaceShaderValues(std::string& vs, std::string& gs, std::string& fs,
                                          vtkAbstractMapper* mapper, vtkProp*) {
  if (!vtkOpenGLPolyDataMapper::SafeDownCast(mapper)) return true;
  // With a geometry shader (wide lines) VTK renames the fragment inputs to GSOut: the baked value
  // does not pass through one, so such draws write 0.
  const bool bakedInput = Options.bakedAO && gs.empty() && vs.find("aokitBakedAOVSOutput") != std::string::npos;
  vtkShaderProgram::Substitute(fs, "//AOKIT::GBuffer::Dec",
                               std::string("uniform float aokitFlags;\nuniform float aokitInstanceId;\nuniform int "
                                           "aokitParallel;\n") +
                                   (bakedInput ? "in vec2 aokitBakedAOVSOutput;\n" : ""),
                               false);
  std::string impl;
  if (fs.find("vertexVC") != std::string::npos && fs.find("normalVCVSOutput") != std::string::npos) {
    std::string code = GBufferOutputFS;
    // Absent targets still get numbers of existing outputs (their code is #if'd out, but VTK
    // declares every gl_FragData[n] it finds): baked AO follows the flags, ids come last.
    const int flags = Attachment(GBufferTarget::Flags);
    vtkShaderProgram::Substitute(code, "@FLAGS@", std::to_string(flags), true);
    vtkShaderProgram::Substitute(code, "@IDS@", std::to_string(Attachments() - 1), true);
    vtkShaderProgram::Substitute(code, "@BAKED@", std::to_string(flags + 1), true);
    impl = std::string("#define AOKIT_GBUFFER_LEAN ") + (Options.lean ? "1" : "0") + "\n#define AOKIT_GBUFFER_IDS " +
           (Options.instanceIds ? "1" : "0") + "\n#define AOKIT_GBUFFER_FACET " + (Options.facetNormals ? "1" : "0") +
           "\n#define AOKIT_GBUFFER_BAKED " + (Options.bakedAO ? "1" : "0") +
           "\n#define AOKIT_GBUFFER_BAKED_VALUE " + (bakedInput ? "(aokitBackSide ? aokitBakedAOVSOutput.y : aokitBakedAOVSOutput.x)" : "0.0") +
           "\n" + code;
  } else {
    // Without the varyings (no lighting, no normals) the surface cannot be described: leave it
    // out of the G-buffer rather than write garbage.
    for (int i = 1; i < Attachments(); ++i) impl += "gl_FragData[" + std::to_string(i) + "] = vec4(0.0);\n";
  }
  vtkShaderProgram::Substitute(fs, "//AOKIT::GBuffer::Impl", impl, false);
  return true;
}

bool GBufferPass::SetShaderParameters(vtkShaderProgram* program, vtkAbstractMapper* mapper, vtkProp* prop,
                                      vtkOpenGLVertexArrayObject*) {
  const bool polyData = vtkOpenGLPolyDataMapper::SafeDownCast(mapper) != nullptr;
  ActivateDrawBuffers(polyData ? Attachments() : 1);
  // The targets beside the colour take what the shader writes, not a blend with what lies below:
  // lines and points write "no surface" (zeros) there (VTK keeps blending on for opaque geometry,
  // and enables it for all buffers at once, so this is said again before every draw).
  for (int i = 1; polyData && i < Attachments(); ++i) glDisablei(GL_BLEND, static_cast<GLuint>(i));
  if (polyData && program->IsUniformUsed("aokitFlags")) {
    const int flags = 1 + (propReceivesAO(prop) ? 2 : 0) + (propCastsAO(prop) ? 4 : 0) + (propDynamic(prop) ? 8 : 0);
    program->SetUniformf("aokitFlags", flags / 255.0f);
    program->SetUniformf("aokitInstanceId", static_cast<float>(propInstanceId(prop)));
    program->SetUniformi("aokitParallel", Parallel ? 1 : 0);
    if (Options.bakedAO) program->SetUniformf("aokitBakedScale", hasBakedAO(vtkActor::SafeDownCast(prop)) ? 1.0f : 0.0f);
  }
  return true;
}

void GBufferPass::ActivateDrawBuffers(int count) { activateDrawBuffers(Framebuffer, count); }

bool GBufferPass::ReadBack(std::vector<float>& positionsVC, std::vector<float>& normalsVC) {
  if (!Framebuffer || Width == 0 || Options.lean) return false;
  const std::size_t n = static_cast<std::size_t>(Width) * Height * 4;
  positionsVC.resize(n);
  normalsVC.resize(n);
  Framebuffer->SaveCurrentBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  Framebuffer->Bind(GL_READ_FRAMEBUFFER);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_COLOR_ATTACHMENT0 + Attachment(GBufferTarget::Position));
  glReadPixels(0, 0, Width, Height, GL_RGBA, GL_FLOAT, positionsVC.data());
  glReadBuffer(GL_COLOR_ATTACHMENT0 + Attachment(GBufferTarget::Normal));
  glReadPixels(0, 0, Width, Height, GL_RGBA, GL_FLOAT, normalsVC.data());
  Framebuffer->UnBind(GL_READ_FRAMEBUFFER);
  Framebuffer->RestorePreviousBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  return true;
}

bool GBufferPass::ReadFlags(std::vector<std::uint8_t>& flags) {
  if (!Framebuffer || Width == 0) return false;
  flags.resize(static_cast<std::size_t>(Width) * Height);
  Framebuffer->SaveCurrentBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  Framebuffer->Bind(GL_READ_FRAMEBUFFER);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadBuffer(GL_COLOR_ATTACHMENT0 + Attachment(GBufferTarget::Flags));
  glReadPixels(0, 0, Width, Height, GL_RED, GL_UNSIGNED_BYTE, flags.data());
  Framebuffer->UnBind(GL_READ_FRAMEBUFFER);
  Framebuffer->RestorePreviousBindingsAndBuffers(GL_READ_FRAMEBUFFER);
  return true;
}

std::size_t GBufferPass::MemoryBytes() const {
  return static_cast<std::size_t>(Width) * Height * gbufferBytesPerPixel(Options);
}

void GBufferPass::ReleaseGraphicsResources(vtkWindow* w) {
  Superclass::ReleaseGraphicsResources(w);
  if (Delegate) Delegate->ReleaseGraphicsResources(w);
  // CopyQuad's program is the window's shader cache's (FullScreenStage::release).
  delete CopyQuad;
  CopyQuad = nullptr;
  for (auto& t : Targets) t = nullptr;
  DepthTexture = nullptr;
  Framebuffer = nullptr;
  Width = Height = GuardX = GuardY = 0;
}

}  // namespace aokit
