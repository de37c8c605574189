#include "render/DeferredAOPass.h"

#include <stdexcept>

#include <vtkOpenGLError.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkRenderState.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "DeferredCombineFS.h"
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

// What the plan's configuration must hold whatever the family says (its settings are validated
// by their schema; this guards the family's own additions).
void check(const DeferredConfig& c) {
  if (c.downsample != 1 && c.downsample != 2 && c.downsample != 4)
    throw std::invalid_argument("deferred AO: downsample must be 1, 2 or 4");
  if (c.aoChannels != 1 && c.aoChannels != 4) throw std::invalid_argument("deferred AO: AO channels must be 1 or 4");
  if (!(c.radius > 0.0)) throw std::invalid_argument("deferred AO: radius must be positive");
}

}  // namespace

DeferredAOPass::DeferredAOPass() : CombineStage("combine", DeferredCombineFS), AOOutputStage("AO output", DeferredCombineFS) {
  GBuffer->SetLean(true);  // positions come from the depth buffer
}

DeferredAOPass::~DeferredAOPass() = default;

void DeferredAOPass::SetDelegatePass(vtkRenderPass* delegate) {
  GBuffer->SetDelegatePass(delegate);
  Modified();
}

vtkRenderPass* DeferredAOPass::GetDelegatePass() const { return GBuffer->GetDelegatePass(); }

void DeferredAOPass::SetSceneRadius(double r) {
  if (r == SceneRadius) return;
  SceneRadius = r;
  Modified();
}

void DeferredAOPass::SetSceneFalloff(Falloff f) {
  if (f == SceneFalloff) return;
  SceneFalloff = f;
  Modified();
}

std::string DeferredAOPass::CombineDefines(bool outputAO) const {
  const DeferredConfig& c = Frame.config;
  const int upsample = c.upsample.window > 0 ? 2 : c.downsample > 1 ? 1 : 0;
  const int view = c.view == DebugView::AO || c.view == DebugView::Normals || c.view == DebugView::Depth
                       ? static_cast<int>(c.view)
                       : 0;
  return "#define AO_TRANSFER " + std::to_string(c.aoChannels == 4 ? 1 : 0) +
         "\n#define AO_SCALAR(v) " + (c.aoChannels == 4 ? "(v).a" : "(v).r") +
         "\n#define AO_UPSAMPLE " + std::to_string(upsample) +
         "\n#define AO_OUTPUT " + std::to_string(outputAO ? 1 : 0) +
         "\n#define AO_BAKED " + std::to_string(c.bakedAO ? 1 : 0) +
         "\n#define AO_DEBUG_VIEW " + std::to_string(view) + "\n";
}

// Builds every program of the plan and the pipeline's own; the name of the first that fails.
const char* DeferredAOPass::Ready(const DeferredPlan& plan) {
  for (const auto& [stage, defines] : plan.stages)
    if (!stage->ready(Frame.renWin, defines)) return stage->name().c_str();
  for (const auto& [name, build] : plan.programs)
    if (!build()) return name.c_str();
  if (!CombineStage.ready(Frame.renWin, CombineDefines(false))) return "combine";
  return nullptr;
}

void DeferredAOPass::AllocateTargets() {
  const int ds = Frame.config.downsample;
  // On-screen pixels only: the guard band is read by the AO stage, never shaded.
  Frame.targetWidth = (Frame.screenWidth + ds - 1) / ds;
  Frame.targetHeight = (Frame.screenHeight + ds - 1) / ds;
  if (!Framebuffer) {
    Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    Framebuffer->SetContext(Frame.renWin);
  }
  const TexFormat format = Frame.config.aoChannels == 4 ? TexFormat::RGBA32F : TexFormat::R32F;
  ensureTexture2D(AOTarget, Frame.renWin, format, Frame.targetWidth, Frame.targetHeight);
  ensureTexture2D(ZTarget, Frame.renWin, TexFormat::R32F, Frame.targetWidth, Frame.targetHeight);
  Upsampler.allocate(Frame);
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

  // 1. The plan, and every program built before drawing: if one fails, the G-buffer shows the
  // frame without AO.
  Frame.renderer = r;
  Frame.renWin = renWin;
  Frame.state = state;
  Frame.context = resolveFrameContext(CommonSettings(), SceneRadius, SceneFalloff, r);
  DeferredPlan plan;
  plan.renWin = renWin;
  plan.config = makeDeferredConfig(CommonSettings(), Frame.context);
  Plan(Frame.context, plan);
  check(plan.config);
  Frame.config = plan.config;
  Upsampler.plan(plan, CombineDefines(false));
  GBuffer->SetGuardBand(Frame.config.guard);
  GBuffer->SetInstanceIds(Frame.config.instanceIds);
  GBuffer->SetBakedAO(Frame.config.bakedAO);
  Timer.begin();
  const char* failed = Ready(plan);
  if (failed && ReportedFailure != failed + CombineDefines(false)) {
    vtkErrorMacro("the " << failed << " stage did not compile (log above); showing the frame without AO");
    ReportedFailure = failed + CombineDefines(false);
  }

  // 2. The G-buffer.
  GBuffer->SetCopyToOutput(failed != nullptr);
  GBuffer->Render(s);
  NumberOfRenderedProps = GBuffer->GetNumberOfRenderedProps();
  Frame.mark("gbuffer");
  if (failed) return;

  // 3. The family's AO stages, 4. upsampling.
  Frame.setView(r, GBuffer);
  Frame.timer = &Timer;
  AllocateTargets();
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  ActiveTextures gbufferTextures{GBuffer->GetDepthTexture(), GBuffer->GetNormalTexture(), GBuffer->GetColorTexture(),
                                 GBuffer->GetFlagsTexture()};
  Result = RenderAO(Frame);
  const bool filtering = Frame.config.upsample.window > 0;
  const bool upsampled = Result && (!filtering || Upsampler.run(Frame, Result));
  if (upsampled && filtering) Frame.mark("upsample");

  // 5. The combine, 6. the overlay.
  int x, y, w, h;
  r->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  state->vtkglViewport(x, y, w, h);
  state->vtkglScissor(x, y, w, h);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(GL_TRUE);
  if (!upsampled) {  // a stage failed after the G-buffer: show the frame without AO
    GBuffer->CopyToFramebuffer(renWin);
    return;
  }
  HasFrame = Combine(CombineStage, false, [&] { CombineStage.render(); });
  Frame.mark("combine");
  if (HasFrame && plan.overlay) {
    state->vtkglDisable(GL_DEPTH_TEST);
    RenderOverlay(Frame);
  }
  vtkOpenGLCheckErrorMacro("failed after DeferredAOPass::Render");
}

template <class Draw>
bool DeferredAOPass::Combine(FullScreenStage& stage, bool outputAO, Draw&& draw) {
  vtkShaderProgram* p = outputAO ? stage.ready(Frame.renWin, CombineDefines(true)) : stage.use(Frame.renWin);
  if (!p) return false;
  ActiveTextures inputs{Result, ZTarget, Upsampler.rows(), Upsampler.guide(), GBuffer->GetBakedAOTexture()};
  Frame.bindCommon(p);
  p->SetUniformi("aoResult", Result->GetTextureUnit());
  p->SetUniformi("aoResultZ", ZTarget->GetTextureUnit());
  Upsampler.bindRows(p);
  if (Frame.config.bakedAO) p->SetUniformi("aoBaked", GBuffer->GetBakedAOTexture()->GetTextureUnit());
  p->SetUniformi("aoDownsample", Frame.config.downsample);
  p->SetUniformf("aoTolerance", static_cast<float>(Frame.config.upsample.depthTolerance));
  p->SetUniformf("aoRadius", static_cast<float>(Frame.config.radius));
  DeferredUpsampler::setKernelUniforms(p, Frame.config);
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
  const bool ok = Combine(AOOutputStage, true, [&] {
    AOOutputStage.renderInto(Framebuffer, {target});
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
  return GBuffer->MemoryBytes() + textureBytes(AOTarget) + textureBytes(ZTarget) + Upsampler.memoryBytes() +
         FamilyMemoryBytes();
}

void DeferredAOPass::ReleaseGraphicsResources(vtkWindow* w) {
  Superclass::ReleaseGraphicsResources(w);
  GBuffer->ReleaseGraphicsResources(w);
  Upsampler.release(w);
  CombineStage.release(w);
  AOOutputStage.release(w);
  ReleaseFamily(w);
  if (auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(w)) {
    renWin->MakeCurrent();
    Timer.release();
  }
  AOTarget = ZTarget = nullptr;
  Result = nullptr;
  Framebuffer = nullptr;
  Frame = DeferredFrame{};
  HasFrame = false;
}

}  // namespace aokit
