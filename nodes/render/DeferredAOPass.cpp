#include "render/DeferredAOPass.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/glm.hpp>
#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkOpenGLError.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkPropCollection.h>
#include <vtkRenderState.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "DeferredCombineFS.h"
#include "DeferredUpsampleFS.h"
#include "render/ActorKeys.h"
#include "render/FullScreenStage.h"
#include "render/Textures.h"

namespace aokit {

namespace {

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

void validate(const DeferredConfig& c) {
  if (c.downsample != 1 && c.downsample != 2 && c.downsample != 4)
    throw std::invalid_argument("deferred AO: downsample must be 1, 2 or 4");
  if (c.aoChannels != 1 && c.aoChannels != 4) throw std::invalid_argument("deferred AO: AO channels must be 1 or 4");
  if (c.upsample.window < 0 || c.upsample.window > 64)
    throw std::invalid_argument("deferred AO: upsampling window must be 0..64 pixels");
  if (!(c.upsample.normalSupport > 0.0 && c.upsample.normalSupport <= 2.0))
    throw std::invalid_argument("deferred AO: normal support must be in (0, 2]");
  if (!(c.upsample.depthTolerance > 0.0 && c.upsample.depthTolerance <= 1.0))
    throw std::invalid_argument("deferred AO: depth tolerance must be in (0, 1]");
  if (!(c.radius > 0.0) || !std::isfinite(c.radius)) throw std::invalid_argument("deferred AO: radius must be positive");
}

// Active for the whole AO phase of a frame: the G-buffer textures every stage may sample.
class ActiveTextures {
 public:
  explicit ActiveTextures(std::initializer_list<vtkTextureObject*> textures) {
    for (vtkTextureObject* t : textures)
      if (t) {
        t->Activate();
        active_.push_back(t);
      }
  }
  ~ActiveTextures() {
    for (auto it = active_.rbegin(); it != active_.rend(); ++it) (*it)->Deactivate();
  }
  ActiveTextures(const ActiveTextures&) = delete;
  ActiveTextures& operator=(const ActiveTextures&) = delete;

 private:
  std::vector<vtkTextureObject*> active_;
};

// The separable upsampler's domain weights per tap: entry o + r + ds - 1 holds the sum of
// w(|o + t|, m) over t = 0..ds-1 with |o + t| <= r = m / 2, the weight of a texel whose first
// pixel lies o pixels from the filtered one (DeferredUpsampleFS.glsl). Wendland as the shaders
// write it.
std::vector<float> domainWeights(int m, int ds) {
  auto wendland = [](float t, float h) {
    const float q = std::clamp(t / h, 0.0f, 1.0f), a = 1.0f - q;
    return a * a * a * a * (4.0f * q + 1.0f);
  };
  const int r = m / 2;
  std::vector<float> out(static_cast<std::size_t>(2 * r + ds), 0.0f);
  for (int o = -r - ds + 1; o <= r; ++o) {
    float sum = 0.0f;
    for (int t = 0; t < ds; ++t)
      if (std::abs(o + t) <= r) sum += wendland(static_cast<float>(std::abs(o + t)), static_cast<float>(m));
    out[static_cast<std::size_t>(o + r + ds - 1)] = sum;
  }
  return out;
}

}  // namespace

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

DeferredAOPass::DeferredAOPass()
    : UpsampleStage(std::make_unique<FullScreenStage>("upsample", DeferredUpsampleFS)),
      CombineStage(std::make_unique<FullScreenStage>("combine", DeferredCombineFS)),
      AOOutputStage(std::make_unique<FullScreenStage>("AO output", DeferredCombineFS)) {
  GBuffer->SetLean(true);  // positions come from the depth buffer
}

DeferredAOPass::~DeferredAOPass() = default;

void DeferredAOPass::SetDelegatePass(vtkRenderPass* delegate) {
  GBuffer->SetDelegatePass(delegate);
  Modified();
}

vtkRenderPass* DeferredAOPass::GetDelegatePass() const { return GBuffer->GetDelegatePass(); }

std::string DeferredAOPass::CombineDefines(bool outputAO) const {
  const DeferredConfig& c = Frame.config;
  const int upsample = c.upsample.window > 0 ? 2 : c.downsample > 1 ? 1 : 0;
  return "#define AO_TRANSFER " + std::to_string(c.aoChannels == 4 ? 1 : 0) +
         "\n#define AO_SCALAR(v) " + (c.aoChannels == 4 ? "(v).a" : "(v).r") +
         "\n#define AO_UPSAMPLE " + std::to_string(upsample) +
         "\n#define AO_NORMAL_KERNEL " + std::to_string(c.upsample.normalKernel ? 1 : 0) +
         "\n#define AO_RANGE_KERNEL " + std::to_string(c.upsample.aoRange > 0.0 ? 1 : 0) +
         "\n#define AO_OUTPUT " + std::to_string(outputAO ? 1 : 0) +
         "\n#define AO_BAKED " + std::to_string(c.bakedAO ? 1 : 0) +
         "\n#define AO_DEBUG_VIEW " + std::to_string(static_cast<int>(c.debugView)) + "\n";
}

void DeferredAOPass::AllocateTargets(vtkOpenGLRenderWindow* renWin) {
  const int ds = Frame.config.downsample;
  // On-screen pixels only: the guard band is read by the AO stage, never shaded.
  const int w = (Frame.screenWidth + ds - 1) / ds, h = (Frame.screenHeight + ds - 1) / ds;
  if (!Framebuffer) {
    Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    Framebuffer->SetContext(renWin);
  }
  const TexFormat format = Frame.config.aoChannels == 4 ? TexFormat::RGBA32F : TexFormat::R32F;
  if (!AOTarget || AllocatedChannels != Frame.config.aoChannels) {
    AllocatedChannels = Frame.config.aoChannels;
    AOTarget = makeTexture2D(renWin, format, w, h);
    ZTarget = makeTexture2D(renWin, TexFormat::R32F, w, h);
    RowTarget = RowGuide = nullptr;
  } else if (w != Frame.targetWidth || h != Frame.targetHeight) {
    AOTarget->Resize(w, h);
    ZTarget->Resize(w, h);
  }
  if (Frame.config.upsample.window > 0) {
    if (!RowTarget) {
      RowTarget = makeTexture2D(renWin, format, Frame.screenWidth, h);
      RowGuide = makeTexture2D(renWin, TexFormat::RGBA32F, Frame.screenWidth, h);
    } else if (static_cast<int>(RowTarget->GetWidth()) != Frame.screenWidth || static_cast<int>(RowTarget->GetHeight()) != h) {
      RowTarget->Resize(Frame.screenWidth, h);
      RowGuide->Resize(Frame.screenWidth, h);
    }
  } else {
    RowTarget = RowGuide = nullptr;
  }
  Frame.targetWidth = w;
  Frame.targetHeight = h;
  Frame.aoTarget = AOTarget;
  Frame.zTarget = ZTarget;
  Frame.fbo = Framebuffer;
}

void DeferredAOPass::Render(const vtkRenderState* s) {
  vtkOpenGLClearErrorMacro();
  NumberOfRenderedProps = 0;
  HasFrame = false;
  vtkRenderer* r = s->GetRenderer();
  auto* renWin = static_cast<vtkOpenGLRenderWindow*>(r->GetRenderWindow());
  vtkOpenGLState* state = renWin->GetState();
  StateGuards guards(state);

  Frame.config = Configure(r);
  validate(Frame.config);
  GBuffer->SetGuardBand(Frame.config.guard);
  GBuffer->SetInstanceIds(Frame.config.instanceIds);
  GBuffer->SetBakedAO(Frame.config.bakedAO);
  Frame.renderer = r;
  Frame.renWin = renWin;
  Frame.state = state;
  Frame.hasNonCasters = false;
  vtkPropCollection* props = r->GetViewProps();
  vtkCollectionSimpleIterator it;
  props->InitTraversal(it);
  while (vtkProp* p = props->GetNextProp(it))
    if (p->GetVisibility() && !propCastsAO(p)) Frame.hasNonCasters = true;
  Timer.begin();

  // Build every program before drawing: if one fails, the G-buffer shows the frame without AO.
  const char* failed = ReadyFamily(Frame);
  if (!failed && Frame.config.upsample.window > 0 && !UpsampleStage->ready(renWin, CombineDefines(false)))
    failed = "upsample";
  if (!failed && !CombineStage->ready(renWin, CombineDefines(false))) failed = "combine";
  if (failed && ReportedFailure != failed + CombineDefines(false)) {
    vtkErrorMacro("the " << failed << " stage did not compile (log above); showing the frame without AO");
    ReportedFailure = failed + CombineDefines(false);
  }
  GBuffer->SetCopyToOutput(failed != nullptr);
  GBuffer->Render(s);
  NumberOfRenderedProps = GBuffer->GetNumberOfRenderedProps();
  Frame.mark("gbuffer");
  if (failed) return;

  // The frame as the family sees it.
  int x, y, w, h;
  r->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  Frame.gbuffer = GBuffer;
  Frame.timer = &Timer;
  Frame.screenWidth = GBuffer->GetScreenWidth();
  Frame.screenHeight = GBuffer->GetScreenHeight();
  vtkMatrix4x4* proj = GBuffer->GetProjection();
  for (int j = 0; j < 4; ++j) {
    Frame.clip[0][j] = static_cast<float>(proj->GetElement(0, j));
    Frame.clip[1][j] = static_cast<float>(proj->GetElement(1, j));
    Frame.clip[2][j] = static_cast<float>(proj->GetElement(3, j));
  }
  // ndc z = (A z + B) / (C z + D): enough to turn window depth back into view z (both projections).
  Frame.depthToZ[0] = static_cast<float>(proj->GetElement(2, 2));
  Frame.depthToZ[1] = static_cast<float>(proj->GetElement(2, 3));
  Frame.depthToZ[2] = static_cast<float>(proj->GetElement(3, 2));
  Frame.depthToZ[3] = static_cast<float>(proj->GetElement(3, 3));
  vtkMatrix4x4* view = r->GetActiveCamera()->GetModelViewTransformMatrix();
  glm::dmat4 worldToView;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Frame.worldToView[i * 4 + j] = view->GetElement(i, j);
      worldToView[j][i] = view->GetElement(i, j);
    }
  const glm::dmat4 viewToWorld = glm::inverse(worldToView);
  for (int c = 0; c < 4; ++c)
    for (int rr = 0; rr < 4; ++rr) Frame.viewToWorld[c * 4 + rr] = static_cast<float>(viewToWorld[c][rr]);

  AllocateTargets(renWin);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  ActiveTextures gbufferTextures{GBuffer->GetDepthTexture(), GBuffer->GetNormalTexture(), GBuffer->GetColorTexture(),
                                 GBuffer->GetFlagsTexture()};
  Result = RenderAO(Frame);
  const bool upsampled = Result && (Frame.config.upsample.window == 0 || RenderUpsample(Result));
  if (upsampled && Frame.config.upsample.window > 0) Frame.mark("upsample");

  state->vtkglViewport(x, y, w, h);
  state->vtkglScissor(x, y, w, h);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(GL_TRUE);
  if (!upsampled) {  // a stage failed after the G-buffer: show the frame without AO
    GBuffer->CopyToFramebuffer(renWin);
    return;
  }
  HasFrame = Combine(*CombineStage, false, [&] { CombineStage->render(); });
  Frame.mark("combine");
  vtkOpenGLCheckErrorMacro("failed after DeferredAOPass::Render");
}

bool DeferredAOPass::RenderUpsample(vtkTextureObject* ao) {
  vtkShaderProgram* p = UpsampleStage->ready(Frame.renWin, CombineDefines(false));
  if (!p) return false;
  ActiveTextures inputs{ao};
  Frame.bindCommon(p);
  p->SetUniformi("aoResult", ao->GetTextureUnit());
  p->SetUniformi("aoDownsample", Frame.config.downsample);
  p->SetUniformi("aoWindow", Frame.config.upsample.window);
  const double radius = Frame.config.upsample.positionRadius > 0.0 ? Frame.config.upsample.positionRadius : Frame.config.radius;
  p->SetUniformf("aoPositionRadius", static_cast<float>(radius));
  p->SetUniformf("aoNormalSupport", static_cast<float>(Frame.config.upsample.normalSupport));
  p->SetUniformf("aoRange", static_cast<float>(Frame.config.upsample.aoRange));
  const std::vector<float> domain = domainWeights(Frame.config.upsample.window, Frame.config.downsample);
  p->SetUniform1fv("aoDomainWeights", static_cast<int>(domain.size()), domain.data());
  UpsampleStage->renderInto(Framebuffer, {RowTarget, RowGuide});
  return true;
}

template <class Draw>
bool DeferredAOPass::Combine(FullScreenStage& stage, bool outputAO, Draw&& draw) {
  vtkShaderProgram* p = stage.ready(Frame.renWin, CombineDefines(outputAO));
  if (!p) return false;
  ActiveTextures inputs{Result, ZTarget, RowTarget.Get(), RowGuide.Get(), GBuffer->GetBakedAOTexture()};
  Frame.bindCommon(p);
  p->SetUniformi("aoResult", Result->GetTextureUnit());
  p->SetUniformi("aoResultZ", ZTarget->GetTextureUnit());
  if (RowTarget) p->SetUniformi("aoRows", RowTarget->GetTextureUnit());
  if (Frame.config.bakedAO) p->SetUniformi("aoBaked", GBuffer->GetBakedAOTexture()->GetTextureUnit());
  if (RowGuide) p->SetUniformi("aoRowGuide", RowGuide->GetTextureUnit());
  p->SetUniformi("aoDownsample", Frame.config.downsample);
  p->SetUniformf("aoTolerance", static_cast<float>(Frame.config.upsample.depthTolerance));
  p->SetUniformf("aoRadius", static_cast<float>(Frame.config.radius));
  p->SetUniformi("aoWindow", Frame.config.upsample.window);
  const double radius = Frame.config.upsample.positionRadius > 0.0 ? Frame.config.upsample.positionRadius : Frame.config.radius;
  p->SetUniformf("aoPositionRadius", static_cast<float>(radius));
  p->SetUniformf("aoNormalSupport", static_cast<float>(Frame.config.upsample.normalSupport));
  p->SetUniformf("aoRange", static_cast<float>(Frame.config.upsample.aoRange));
  if (Frame.config.upsample.window > 0) {
    const std::vector<float> domain = domainWeights(Frame.config.upsample.window, Frame.config.downsample);
    p->SetUniform1fv("aoDomainWeights", static_cast<int>(domain.size()), domain.data());
  }
  draw();
  return true;
}

bool DeferredAOPass::ReadAO(vtkOpenGLRenderWindow* renWin, std::vector<float>& ao, std::vector<std::uint8_t>* covered) {
  if (!HasFrame) return false;
  const int w = Frame.screenWidth, h = Frame.screenHeight;
  const bool rgba = Frame.config.aoChannels == 4;
  vtkOpenGLState* state = renWin->GetState();
  StateGuards guards(state);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);

  // Full resolution only while reading: the pipeline itself keeps no full-resolution AO buffer.
  auto target = makeTexture2D(renWin, rgba ? TexFormat::RGBA32F : TexFormat::R32F, w, h);
  std::vector<float> pixels(static_cast<std::size_t>(w) * h * (rgba ? 4 : 1));
  ActiveTextures gbufferTextures{GBuffer->GetDepthTexture(), GBuffer->GetNormalTexture(), GBuffer->GetColorTexture(),
                                 GBuffer->GetFlagsTexture()};
  const bool ok = Combine(*AOOutputStage, true, [&] {
    AOOutputStage->renderInto(Framebuffer, {target});
    state->PushReadFramebufferBinding();
    Framebuffer->Bind(GL_READ_FRAMEBUFFER);
    Framebuffer->AddColorAttachment(0, target);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, rgba ? GL_RGBA : GL_RED, GL_FLOAT, pixels.data());
    Framebuffer->RemoveColorAttachment(0);
    state->PopReadFramebufferBinding();
  });
  target->ReleaseGraphicsResources(renWin);
  if (!ok) {
    vtkErrorMacro("the AO output stage did not compile (log above)");
    return false;
  }
  // The AO output marks background -1 (a = 0 with four channels).
  ao.resize(static_cast<std::size_t>(w) * h);
  if (covered) covered->resize(ao.size());
  for (std::size_t i = 0; i < ao.size(); ++i) {
    const bool c = rgba ? pixels[4 * i + 3] > 0.5f : pixels[i] >= 0.0f;
    ao[i] = !c ? 0.0f : rgba ? (pixels[4 * i] + pixels[4 * i + 1] + pixels[4 * i + 2]) / 3.0f : pixels[i];
    if (covered) (*covered)[i] = c;
  }
  vtkOpenGLCheckErrorMacro("failed after DeferredAOPass::ReadAO");
  return true;
}

std::size_t DeferredAOPass::MemoryBytes() const {
  return GBuffer->MemoryBytes() + textureBytes(AOTarget) + textureBytes(ZTarget) + textureBytes(RowTarget) +
         textureBytes(RowGuide) +
         FamilyMemoryBytes();
}

void DeferredAOPass::ReleaseGraphicsResources(vtkWindow* w) {
  Superclass::ReleaseGraphicsResources(w);
  GBuffer->ReleaseGraphicsResources(w);
  UpsampleStage->release(w);
  CombineStage->release(w);
  AOOutputStage->release(w);
  ReleaseFamily(w);
  if (auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(w)) {
    renWin->MakeCurrent();
    Timer.release();
  }
  AOTarget = ZTarget = RowTarget = RowGuide = nullptr;
  Result = nullptr;
  Framebuffer = nullptr;
  AllocatedChannels = 0;
  Frame = DeferredFrame{};
  HasFrame = false;
}

}  // namespace aokit
