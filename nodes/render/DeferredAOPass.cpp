#include "render/DeferredAOPass.h"

#include <stdexcept>

#include <vtkCameraPass.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLError.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkRenderState.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtkWeakPointer.h>
#include <vtk_glew.h>

#include "DeferredCombineFS.h"
#include "parallel/GBufferComposite.h"
#include "parallel/RankExchange.h"
#include "render/AfterOpaque.h"
#include "render/DeferredView.h"
#include "render/SelectionGeometry.h"
#include "render/StateGuards.h"
#include "render/DeferredUpsampler.h"
#include "render/Textures.h"

namespace aokit {

namespace {

// What the plan's configuration must hold whatever the family says (its settings are validated
// by their schema; this guards the family's own additions).
void check(const DeferredConfig& c) {
  if (c.downsample != 1 && c.downsample != 2 && c.downsample != 4)
    throw std::invalid_argument("deferred AO: downsample must be 1, 2 or 4");
  if (c.aoChannels != 1 && c.aoChannels != 4) throw std::invalid_argument("deferred AO: AO channels must be 1 or 4");
  if (!(c.radius > 0.0)) throw std::invalid_argument("deferred AO: radius must be positive");
}

// The combine's 1 - AO multiplies the colour already in the frame; its alpha stays.
template <class Draw>
void multiplyOntoFrame(vtkOpenGLState* state, Draw&& draw) {
  state->vtkglEnable(GL_BLEND);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  state->vtkglBlendFuncSeparate(GL_DST_COLOR, GL_ZERO, GL_ZERO, GL_ONE);
  draw();
  state->vtkglDisable(GL_BLEND);
}

}  // namespace

DeferredAOPass::DeferredAOPass()
    : After(std::make_unique<AfterOpaque>()), CombineStage("combine", DeferredCombineFS),
      AOOutputStage("AO output", DeferredCombineFS), MultiplyStage("AO multiply", DeferredCombineFS) {}

DeferredAOPass::~DeferredAOPass() = default;

void DeferredAOPass::ReleaseOnDestroy() {
  if (LastWindow) ReleaseGraphicsResources(LastWindow);
}

void DeferredAOPass::SetDelegatePass(vtkRenderPass* delegate) {
  Delegate = delegate;
  for (auto& [renderer, view] : Views) {
    view->gbuffer->SetDelegatePass(GBufferDelegate());
    view->opaque = nullptr;
  }
  Modified();
}

vtkRenderPass* DeferredAOPass::GetDelegatePass() const { return Delegate; }

void DeferredAOPass::SetSceneRadius(double r) {
  if (r == SceneRadius) return;
  SceneRadius = r;
  Modified();
}

void DeferredAOPass::SetRankExchange(std::shared_ptr<RankExchange> ranks) {
  if (ranks == Ranks) return;
  Ranks = std::move(ranks);
  Modified();
}

void DeferredAOPass::SetSceneFalloff(Falloff f) {
  if (f == SceneFalloff) return;
  SceneFalloff = f;
  Modified();
}

DeferredAOPass::View& DeferredAOPass::ViewOf(vtkRenderer* renderer) {
  for (auto it = Views.begin(); it != Views.end();)  // renderers gone since
    it = it->second->renderer ? std::next(it) : Views.erase(it);
  std::unique_ptr<View>& v = Views[renderer];
  if (!v) {
    v = std::make_unique<View>();
    v->renderer = renderer;
    v->gbuffer->SetLean(true);  // positions come from the depth buffer
    v->gbuffer->SetDelegatePass(GBufferDelegate());
  }
  return *v;
}

const DeferredAOPass::View* DeferredAOPass::FindView(vtkRenderer* renderer) const {
  if (!renderer) return Current;
  const auto it = Views.find(renderer);
  return it != Views.end() && it->second->renderer ? it->second.get() : nullptr;
}

GBufferPass* DeferredAOPass::GetGBufferPass(vtkRenderer* renderer) const {
  const View* v = FindView(renderer);
  return v ? v->gbuffer.Get() : nullptr;
}

std::string DeferredAOPass::CombineDefines(const DeferredConfig& c, CombineOutput output) const {
  const int upsample = c.upsample.window > 0 ? 2 : c.downsample > 1 ? 1 : 0;
  const int view = c.view == DebugView::AO || c.view == DebugView::Normals || c.view == DebugView::Depth
                       ? static_cast<int>(c.view)
                       : 0;
  return "#define AO_TRANSFER " + std::to_string(c.aoChannels == 4 ? 1 : 0) +
         "\n#define AO_SCALAR(v) " + (c.aoChannels == 4 ? "(v).a" : "(v).r") +
         "\n#define AO_UPSAMPLE " + std::to_string(upsample) +
         "\n#define AO_OUTPUT " + std::to_string(output == CombineOutput::AO ? 1 : 0) +
         "\n#define AO_MULTIPLY " + std::to_string(output == CombineOutput::Multiply ? 1 : 0) +
         "\n#define AO_BLEND " + std::to_string(output == CombineOutput::Blend ? 1 : 0) +
         "\n#define AO_BAKED " + std::to_string(c.bakedAO ? 1 : 0) +
         "\n#define AO_DEBUG_VIEW " + std::to_string(view) + "\n";
}

// Builds every program of the plan and the pipeline's own; the name of the first that fails.
const char* DeferredAOPass::Ready(const DeferredPlan& plan, bool multiply, CombineOutput combine) {
  for (const auto& [stage, defines] : plan.stages)
    if (!stage->ready(Frame.renWin, defines)) return stage->name().c_str();
  for (const auto& [name, build] : plan.programs)
    if (!build()) return name.c_str();
  if (!CombineStage.ready(Frame.renWin, CombineDefines(Frame.config, combine))) return "combine";
  if (multiply && !MultiplyStage.ready(Frame.renWin, CombineDefines(Frame.config, CombineOutput::Multiply)))
    return "AO multiply";
  return nullptr;
}

void DeferredAOPass::AllocateTargets(View& v, bool resultTarget) {
  const int ds = Frame.config.downsample;
  // On-screen pixels only: the guard band is read by the AO stage, never shaded.
  Frame.targetWidth = (Frame.screenWidth + ds - 1) / ds;
  Frame.targetHeight = (Frame.screenHeight + ds - 1) / ds;
  if (!v.framebuffer) {
    v.framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    v.framebuffer->SetContext(Frame.renWin);
  }
  const TexFormat format = Frame.config.aoChannels == 4 ? TexFormat::RGBA32F : TexFormat::R32F;
  ensureTexture2D(v.aoTarget, Frame.renWin, format, Frame.targetWidth, Frame.targetHeight);
  ensureTexture2D(v.zTarget, Frame.renWin, TexFormat::R32F, Frame.targetWidth, Frame.targetHeight);
  if (resultTarget) ensureTexture2D(v.resultTarget, Frame.renWin, format, Frame.targetWidth, Frame.targetHeight);
  else v.resultTarget = nullptr;
  v.upsampler.allocate(Frame);
  Frame.aoTarget = v.aoTarget;
  Frame.zTarget = v.zTarget;
  Frame.resultTarget = v.resultTarget;
  Frame.fbo = v.framebuffer;
}

void DeferredAOPass::Render(const vtkRenderState* s) {
  vtkOpenGLClearErrorMacro();
  NumberOfRenderedProps = 0;
  vtkRenderer* r = s->GetRenderer();
  auto* renWin = static_cast<vtkOpenGLRenderWindow*>(r->GetRenderWindow());
  vtkOpenGLState* state = renWin->GetState();
  if (r->GetSelector()) {  // picking: no AO, VTK's own selection rendering
    if (!Selection) {
      auto camera = vtkSmartPointer<vtkCameraPass>::New();
      camera->SetDelegatePass(vtkSmartPointer<SelectionGeometry>::New());
      Selection = camera;
    }
    Selection->Render(s);
    NumberOfRenderedProps = Selection->GetNumberOfRenderedProps();
    return;
  }
  if (LastWindow && LastWindow != renWin) {
    // GL objects live in one window's context: the family's, the stages' and the views' of the
    // window drawn before are released there (drawing in two windows alternately re-uploads them).
    ReleaseGraphicsResources(LastWindow);
    renWin->MakeCurrent();
  }
  StateGuards guards(state);
  View& v = ViewOf(r);
  Current = &v;
  LastWindow = renWin;
  v.hasFrame = false;

  // 1. The plan, and every program built before drawing: if one fails, the G-buffer shows the
  // frame without AO.
  Frame = DeferredFrame{};
  Frame.renderer = r;
  Frame.renWin = renWin;
  Frame.state = state;
  Frame.timer = &Timer;
  Frame.context = resolveFrameContext(CommonSettings(), SceneRadius, SceneFalloff, r, Ranks.get());
  PrepareFrame(r, Frame.context);
  DeferredPlan plan;
  plan.renWin = renWin;
  plan.config = makeDeferredConfig(CommonSettings(), Frame.context);
  Plan(Frame.context, plan);
  check(plan.config);
  Frame.config = plan.config;
  v.upsampler.plan(plan, CombineDefines(Frame.config, CombineOutput::Frame));
  GBufferPass* gbuffer = v.gbuffer;
  gbuffer->SetGuardBand(Frame.config.guard);
  gbuffer->SetInstanceIds(Frame.config.instanceIds);
  gbuffer->SetBakedAO(Frame.config.bakedAO);
  gbuffer->SetFacetNormals(Frame.config.facetNormals);
  const bool multiply = Multisampled(r, Frame.config);
  // The colour reaches a single-sampled frame by a blit; the combine then shades only covered
  // pixels, blended onto it (CombineOutput::Blend).
  GLint drawSamples = 0;
  glGetIntegerv(GL_SAMPLES, &drawSamples);
  const bool blit = !multiply && drawSamples == 0 && Frame.config.view == DebugView::Off;
  Timer.begin();
  const char* failed = Ready(plan, multiply, blit ? CombineOutput::Blend : CombineOutput::Frame);
  if (failed && ReportedFailure != failed + CombineDefines(Frame.config, CombineOutput::Frame)) {
    vtkErrorMacro("the " << failed << " stage did not compile (log above); showing the frame without AO");
    ReportedFailure = failed + CombineDefines(Frame.config, CombineOutput::Frame);
  }

  // 2. The G-buffer.
  gbuffer->SetCopyToOutput(failed != nullptr);
  gbuffer->Render(s);
  NumberOfRenderedProps = gbuffer->GetNumberOfRenderedProps();
  // Every rank's surfaces in every rank's G-buffer (parallel/GBufferComposite.h).
  if (Frame.context.ranks) Frame.context.exchangedBytes += compositeGBuffer(*gbuffer, *Frame.context.ranks);
  Frame.mark("gbuffer");
  if (failed) return RenderAfterOpaque(s);

  // 3. The family's AO stages, 4. upsampling.
  Frame.setView(r, gbuffer);
  AllocateTargets(v, plan.resultTarget);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);
  ActiveTextures gbufferTextures{gbuffer->GetDepthTexture(), gbuffer->GetNormalTexture(), gbuffer->GetColorTexture(),
                                 gbuffer->GetFlagsTexture()};
  int limit = Accumulate > 0 ? Accumulate : Frame.config.accumulate;
  if (Frame.context.ranks && limit > 1) {
    // A rank whose own props changed would restart its mean alone and leave the others' exchanges.
    if (!WarnedParallelAccumulate)
      vtkWarningMacro("accumulation is off on " << Frame.context.ranks->ranks() << " ranks (each frame is drawn anew)");
    WarnedParallelAccumulate = true;
    limit = 1;
  }
  Frame.accumulated = v.accumulator.begin(Frame, GetMTime(), limit);
  v.result = v.accumulator.converged() ? v.accumulator.mean() : v.accumulator.add(Frame, RenderAO(Frame));
  const bool filtering = Frame.config.upsample.window > 0;
  const bool upsampled = v.result && (!filtering || v.upsampler.run(Frame, v.result));
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
    gbuffer->CopyToFramebuffer(renWin);
    return RenderAfterOpaque(s);
  }
  v.frame = Frame;
  if (multiply) {
    // A multisampled window: VTK's own opaque rendering into the window's samples (anti-aliased
    // edges and depth), then each pixel's samples multiplied by its 1 - AO. An edge pixel's
    // samples all take the AO of the surface at its centre.
    if (!v.opaque) v.opaque = GBufferDelegate();
    v.opaque->Render(s);
    state->vtkglViewport(x, y, w, h);
    state->vtkglScissor(x, y, w, h);
    state->vtkglDisable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_FALSE);
    multiplyOntoFrame(state, [&] {
      v.hasFrame = Combine(v, MultiplyStage, CombineOutput::Multiply, [&] { MultiplyStage.render(); });
    });
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthMask(GL_TRUE);
  } else if (blit) {
    // The G-buffer's colour, then each pixel a surface (or line) was drawn on multiplied by its
    // 1 - AO, with its depth; the background's depth is cleared and its pixels discarded unshaded.
    gbuffer->BlitColorToFramebuffer(renWin, x, y);
    state->vtkglClearDepth(1.0);
    state->vtkglClear(GL_DEPTH_BUFFER_BIT);
    multiplyOntoFrame(state, [&] {
      v.hasFrame = Combine(v, CombineStage, CombineOutput::Blend, [&] { CombineStage.render(); });
    });
  } else {
    v.hasFrame = Combine(v, CombineStage, CombineOutput::Frame, [&] { CombineStage.render(); });
  }
  Frame.mark("combine");
  if (v.hasFrame && plan.overlay) {
    state->vtkglDisable(GL_DEPTH_TEST);
    RenderOverlay(Frame);
  }
  RenderAfterOpaque(s);
  vtkOpenGLCheckErrorMacro("failed after DeferredAOPass::Render");
}

// What the G-buffer draws: opaque geometry through VTK's render steps (a user's, when they are
// render steps), or all a user's other delegate draws.
vtkSmartPointer<vtkRenderPass> DeferredAOPass::GBufferDelegate() const {
  auto* steps = vtkRenderStepsPass::SafeDownCast(Delegate);
  if (Delegate && !steps) return Delegate;
  return opaqueSteps(steps);
}

// Whether this frame applies AO to VTK's own multisampled rendering (the G-buffer is single-sampled:
// its combined frame would give every sample of a pixel one value). Not for debug views, nor for a
// user's delegate that is no vtkRenderStepsPass (it may draw more than opaque geometry): that is
// said once.
bool DeferredAOPass::Multisampled(vtkRenderer* r, const DeferredConfig& c) {
  if (r->GetRenderWindow()->GetMultiSamples() <= 1 || c.view != DebugView::Off) return false;
  if (!Delegate || vtkRenderStepsPass::SafeDownCast(Delegate)) return true;
  if (!WarnedMultisamples) {
    vtkWarningMacro("a multisampled window with a delegate pass that is no vtkRenderStepsPass: the frame is not "
                    "anti-aliased (use FXAA)");
    WarnedMultisamples = true;
  }
  return false;
}

// 7. Translucent geometry, volumes and overlays over the frame (AfterOpaque.h), unless a delegate
// of the user's that is no vtkRenderStepsPass drew them into the G-buffer.
void DeferredAOPass::RenderAfterOpaque(const vtkRenderState* s) {
  auto* steps = vtkRenderStepsPass::SafeDownCast(Delegate);
  if (Delegate && !steps) return;
  int x, y, w, h;
  s->GetRenderer()->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  vtkOpenGLState* state = static_cast<vtkOpenGLRenderWindow*>(s->GetRenderer()->GetRenderWindow())->GetState();
  state->vtkglViewport(x, y, w, h);
  state->vtkglScissor(x, y, w, h);
  After->render(s, steps);
}

template <class Draw>
bool DeferredAOPass::Combine(View& v, FullScreenStage& stage, CombineOutput output, Draw&& draw) {
  const DeferredFrame& f = v.frame;
  // The AO output is built when read (the frame's variants were built before drawing).
  vtkShaderProgram* p = output == CombineOutput::AO ? stage.ready(f.renWin, CombineDefines(f.config, output))
                                                    : stage.use(f.renWin);
  if (!p) return false;
  GBufferPass* gbuffer = v.gbuffer;
  ActiveTextures inputs{v.result, v.zTarget, v.upsampler.rows(), v.upsampler.guide(), gbuffer->GetBakedAOTexture()};
  f.bindCommon(p);
  p->SetUniformi("aoResult", v.result->GetTextureUnit());
  p->SetUniformi("aoResultZ", v.zTarget->GetTextureUnit());
  v.upsampler.bindRows(p);
  if (f.config.bakedAO) p->SetUniformi("aoBaked", gbuffer->GetBakedAOTexture()->GetTextureUnit());
  p->SetUniformi("aoDownsample", f.config.downsample);
  p->SetUniformf("aoTolerance", static_cast<float>(f.config.upsample.depthTolerance));
  p->SetUniformf("aoRadius", static_cast<float>(f.config.radius));
  DeferredUpsampler::setKernelUniforms(p, f.config);
  draw();
  return true;
}

bool DeferredAOPass::ReadAO(vtkOpenGLRenderWindow* renWin, std::vector<float>& ao, std::vector<std::uint8_t>* covered,
                            vtkRenderer* renderer) {
  View* v = const_cast<View*>(FindView(renderer));
  if (!v || !v->hasFrame) return false;
  const DeferredFrame& f = v->frame;
  const int w = f.screenWidth, h = f.screenHeight;
  const bool rgba = f.config.aoChannels == 4;
  vtkOpenGLState* state = renWin->GetState();
  StateGuards guards(state);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  state->vtkglDisable(GL_SCISSOR_TEST);

  // Full resolution only while reading: the pipeline itself keeps no full-resolution AO buffer.
  auto target = makeTexture2D(renWin, rgba ? TexFormat::RGBA32F : TexFormat::R32F, w, h);
  std::vector<float> pixels(static_cast<std::size_t>(w) * h * (rgba ? 4 : 1));
  GBufferPass* gbuffer = v->gbuffer;
  ActiveTextures gbufferTextures{gbuffer->GetDepthTexture(), gbuffer->GetNormalTexture(), gbuffer->GetColorTexture(),
                                 gbuffer->GetFlagsTexture()};
  vtkOpenGLFramebufferObject* fbo = v->framebuffer;
  const bool ok = Combine(*v, AOOutputStage, CombineOutput::AO, [&] {
    AOOutputStage.renderInto(fbo, {target});
    state->PushReadFramebufferBinding();
    fbo->Bind(GL_READ_FRAMEBUFFER);
    fbo->AddColorAttachment(0, target);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, rgba ? GL_RGBA : GL_RED, GL_FLOAT, pixels.data());
    fbo->RemoveColorAttachment(0);
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
  std::size_t bytes = FamilyMemoryBytes();
  for (const auto& [renderer, view] : Views) bytes += view->memoryBytes();
  return bytes;
}

void DeferredAOPass::ReleaseGraphicsResources(vtkWindow* w) {
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(w);
  if (renWin) renWin->MakeCurrent();  // objects are deleted in the context that made them
  Superclass::ReleaseGraphicsResources(w);
  for (auto& [renderer, view] : Views) view->release(w);
  Views.clear();
  Current = nullptr;
  if (Delegate) Delegate->ReleaseGraphicsResources(w);
  if (Selection) Selection->ReleaseGraphicsResources(w);
  After->release(w);
  CombineStage.release(w);
  AOOutputStage.release(w);
  MultiplyStage.release(w);
  ReleaseFamily(w);
  if (renWin) Timer.release();
  Frame = DeferredFrame{};
}

}  // namespace aokit
