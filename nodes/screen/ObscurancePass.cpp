#include "screen/ObscurancePass.h"

#include <cmath>

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLError.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkRenderState.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "ObscurancePassCombineFS.h"
#include "ObscurancePassObscuranceFS.h"
#include "screen/ObscuranceFilter.h"
#include "screen/ScreenQuadStage.h"

namespace aokit {

vtkStandardNewMacro(ObscurancePass);

namespace {

const char* const kAOOutputOff = "#define OBS_OUTPUT_AO 0\n";
const char* const kAOOutputOn = "#define OBS_OUTPUT_AO 1\n";

// An AO target: one float (occlusion, view z) or four (the two sums of eq. 9) per pixel; nearest
// sampling, since every stage reads exact texels.
vtkSmartPointer<vtkTextureObject> makeFloatTarget(vtkOpenGLRenderWindow* renWin, bool rgba, int w, int h) {
  auto t = vtkSmartPointer<vtkTextureObject>::New();
  t->SetContext(renWin);
  t->SetInternalFormat(rgba ? GL_RGBA32F : GL_R32F);
  t->SetFormat(rgba ? GL_RGBA : GL_RED);
  t->SetDataType(GL_FLOAT);
  t->SetMinificationFilter(vtkTextureObject::Nearest);
  t->SetMagnificationFilter(vtkTextureObject::Nearest);
  t->SetWrapS(vtkTextureObject::ClampToEdge);
  t->SetWrapT(vtkTextureObject::ClampToEdge);
  t->Allocate2D(w, h, rgba ? 4 : 1, VTK_FLOAT);
  return t;
}

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

}  // namespace

ObscurancePass::ObscurancePass()
    : ObscuranceStage(std::make_unique<ScreenQuadStage>("obscurance", ObscurancePassObscuranceFS)),
      Filter(std::make_unique<ObscuranceFilter>()),
      CombineStage(std::make_unique<ScreenQuadStage>("combine", ObscurancePassCombineFS)),
      AOOutputStage(std::make_unique<ScreenQuadStage>("AO output", ObscurancePassCombineFS)) {
  GBuffer->SetLean(true);  // positions come from the depth buffer
}

ObscurancePass::~ObscurancePass() = default;

void ObscurancePass::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  const char* interleave[] = {"off", "rotations", "shifts"};
  os << indent << "Samples: " << Settings.samples << ", PointsPerRay: " << Settings.pointsPerRay << "\n"
     << indent << "Radius: " << Settings.radius << " (scene " << SceneRadius << ")\n"
     << indent << "Interleave: " << interleave[static_cast<int>(Settings.interleave)]
     << ", Filter: " << Settings.filter << "\n"
     << indent << "SilhouetteElimination: " << Settings.silhouetteElimination
     << ", AmbientTransfer: " << Settings.ambientTransfer << "\n"
     << indent << "ResolutionScale: " << Settings.resolutionScale << ", Guard: " << Settings.guard << "\n";
}

void ObscurancePass::SetDelegatePass(vtkRenderPass* delegate) {
  GBuffer->SetDelegatePass(delegate);
  Modified();
}

vtkRenderPass* ObscurancePass::GetDelegatePass() const { return GBuffer->GetDelegatePass(); }

void ObscurancePass::SetSettings(const ObscuranceSettings& s) {
  validate(s);
  Settings = s;
  GBuffer->SetGuardBand(s.guard);
  ConstantsValid = false;
  Modified();
}

void ObscurancePass::SetSceneRadius(double r) {
  if (r == SceneRadius) return;
  SceneRadius = r;
  ConstantsValid = false;
  Modified();
}

void ObscurancePass::SetSceneFalloff(Falloff f) {
  if (f == SceneFalloff) return;
  SceneFalloff = f;
  ConstantsValid = false;
  Modified();
}

void ObscurancePass::UpdateConstants(vtkRenderer* r) {
  double sceneR = SceneRadius;
  if (Settings.radius <= 0.0 && sceneR <= 0.0) {
    // A plain VTK scene: size the radius from what is visible.
    double b[6];
    r->ComputeVisiblePropBounds(b);
    const double diag = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
                                  (b[5] - b[4]) * (b[5] - b[4]));
    sceneR = (b[0] <= b[1] && std::isfinite(diag) && diag > 0.0) ? 0.1 * diag : 1.0;
  }
  if (ConstantsValid && sceneR == ResolvedSceneRadius) return;
  Constants = makeObscuranceConstants(Settings, sceneR, SceneFalloff);
  ConstantsValid = true;
  ResolvedSceneRadius = sceneR;
}

void ObscurancePass::AllocateTargets(vtkOpenGLRenderWindow* renWin) {
  const int ds = Constants.downsample;
  // On-screen pixels only: the guard band is read by the containment tests, never shaded.
  const int w = (GBuffer->GetScreenWidth() + ds - 1) / ds, h = (GBuffer->GetScreenHeight() + ds - 1) / ds;
  if (!Framebuffer) {
    Framebuffer = vtkSmartPointer<vtkOpenGLFramebufferObject>::New();
    Framebuffer->SetContext(renWin);
  }
  if (!RawTarget || TargetsRGBA != Constants.transfer) {
    TargetsRGBA = Constants.transfer;
    RawTarget = makeFloatTarget(renWin, TargetsRGBA, w, h);
    FilteredTarget = makeFloatTarget(renWin, TargetsRGBA, w, h);
    ZTarget = makeFloatTarget(renWin, false, w, h);
  } else if (w != TargetWidth || h != TargetHeight) {
    RawTarget->Resize(w, h);
    FilteredTarget->Resize(w, h);
    ZTarget->Resize(w, h);
  }
  TargetWidth = w;
  TargetHeight = h;
}

bool ObscurancePass::RenderObscurance(vtkOpenGLRenderWindow* renWin) {
  vtkShaderProgram* p = ObscuranceStage->ready(renWin, Constants.defines());
  if (!p) return false;
  vtkTextureObject* inputs[] = {GBuffer->GetNormalTexture(), GBuffer->GetDepthTexture(), GBuffer->GetColorTexture()};
  const char* names[] = {"obsNormal", "obsDepth", "obsColor"};
  const int count = Constants.transfer ? 3 : 2;
  for (int i = 0; i < count; ++i) {
    inputs[i]->Activate();
    p->SetUniformi(names[i], inputs[i]->GetTextureUnit());
  }
  p->SetUniform3fv("obsOffsets", static_cast<int>(Constants.offsets.size()), &Constants.offsets[0].x);
  // VTK's view -> clip matrix, the one the mappers used for this frame (row-major, column vectors;
  // with a guard band, the enlarged frustum's).
  vtkMatrix4x4* m = GBuffer->GetProjection();
  float rows[4][4];
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) rows[i][j] = static_cast<float>(m->GetElement(i, j));
  p->SetUniform4f("obsClipX", rows[0]);
  p->SetUniform4f("obsClipY", rows[1]);
  p->SetUniform4f("obsClipW", rows[3]);
  // ndc z = (A z + B) / (C z + D): enough to turn window depth back into view z (both projections).
  DepthToZ[0] = rows[2][2];
  DepthToZ[1] = rows[2][3];
  DepthToZ[2] = rows[3][2];
  DepthToZ[3] = rows[3][3];
  p->SetUniform4f("obsDepthToZ", DepthToZ);
  p->SetUniformf("obsRadius", Constants.radius);
  p->SetUniformf("obsBias", Constants.bias);
  p->SetUniformf("obsThickness", Constants.thickness);
  p->SetUniform2i("obsGuard", Guard);
  ObscuranceStage->renderInto(Framebuffer, RawTarget, ZTarget);
  for (int i = count - 1; i >= 0; --i) inputs[i]->Deactivate();
  return true;
}

template <class Draw>
bool ObscurancePass::BindCombine(ScreenQuadStage& stage, vtkOpenGLRenderWindow* renWin, const std::string& defines,
                                 Draw&& draw) {
  vtkShaderProgram* p = stage.ready(renWin, defines);
  if (!p) return false;
  vtkTextureObject* inputs[] = {FilteredTarget, ZTarget, GBuffer->GetColorTexture(), GBuffer->GetDepthTexture(),
                                GBuffer->GetNormalTexture()};
  const char* names[] = {"obsAO", "obsZ", "obsColor", "obsDepth", "obsNormal"};
  const int count = Constants.debugView == static_cast<int>(ObscuranceDebugView::Normals) ? 5 : 4;
  for (int i = 0; i < count; ++i) {
    inputs[i]->Activate();
    p->SetUniformi(names[i], inputs[i]->GetTextureUnit());
  }
  p->SetUniform4f("obsDepthToZ", DepthToZ);
  p->SetUniformf("obsFilterTolerance", Constants.filterTolerance);
  p->SetUniformf("obsRadius", Constants.radius);
  p->SetUniform2i("obsGuard", Guard);
  draw();
  for (int i = count - 1; i >= 0; --i) inputs[i]->Deactivate();
  return true;
}

void ObscurancePass::Render(const vtkRenderState* s) {
  vtkOpenGLClearErrorMacro();
  NumberOfRenderedProps = 0;
  HasFrame = false;
  vtkRenderer* r = s->GetRenderer();
  auto* renWin = static_cast<vtkOpenGLRenderWindow*>(r->GetRenderWindow());
  vtkOpenGLState* state = renWin->GetState();
  StateGuards guards(state);

  UpdateConstants(r);
  const std::string defines = Constants.defines();
  // Build every program before drawing: if one fails, the G-buffer shows the frame without AO.
  const char* failed = !ObscuranceStage->ready(renWin, defines) ? "obscurance"
                       : !Filter->ready(renWin, Constants)      ? "filter"
                       : !CombineStage->ready(renWin, defines + kAOOutputOff) ? "combine"
                                                                              : nullptr;
  if (failed && defines != ReportedFailure) {
    vtkErrorMacro("the " << failed << " stage did not compile (log above); showing the frame without AO");
    ReportedFailure = defines;
  }
  GBuffer->SetCopyToOutput(failed != nullptr);
  GBuffer->Render(s);
  NumberOfRenderedProps = GBuffer->GetNumberOfRenderedProps();
  if (failed) return;

  int x, y, w, h;
  r->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  Guard[0] = GBuffer->GetGuardX();
  Guard[1] = GBuffer->GetGuardY();
  AllocateTargets(renWin);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);
  if (!RenderObscurance(renWin)) return;
  if (!Filter->run(renWin, Framebuffer, RawTarget, ZTarget, FilteredTarget, Constants)) return;

  state->vtkglViewport(x, y, w, h);
  state->vtkglScissor(x, y, w, h);
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(GL_TRUE);
  HasFrame = BindCombine(*CombineStage, renWin, defines + kAOOutputOff, [&] { CombineStage->render(); });
  vtkOpenGLCheckErrorMacro("failed after ObscurancePass::Render");
}

bool ObscurancePass::ReadAO(vtkOpenGLRenderWindow* renWin, std::vector<float>& ao,
                            std::vector<std::uint8_t>* covered) {
  if (!HasFrame) return false;
  const int w = GBuffer->GetScreenWidth(), h = GBuffer->GetScreenHeight();
  vtkOpenGLState* state = renWin->GetState();
  StateGuards guards(state);
  state->vtkglDisable(GL_BLEND);
  state->vtkglDisable(GL_DEPTH_TEST);

  // Full resolution only while reading: the pipeline itself keeps no full-resolution AO buffer.
  auto target = makeFloatTarget(renWin, TargetsRGBA, w, h);
  std::vector<float> pixels(static_cast<std::size_t>(w) * h * (TargetsRGBA ? 4 : 1));
  const bool ok = BindCombine(*AOOutputStage, renWin, Constants.defines() + kAOOutputOn, [&] {
    AOOutputStage->renderInto(Framebuffer, target);
    state->PushReadFramebufferBinding();
    Framebuffer->Bind(GL_READ_FRAMEBUFFER);
    Framebuffer->AddColorAttachment(0, target);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, w, h, TargetsRGBA ? GL_RGBA : GL_RED, GL_FLOAT, pixels.data());
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
    const bool c = TargetsRGBA ? pixels[4 * i + 3] > 0.5f : pixels[i] >= 0.0f;
    ao[i] = !c ? 0.0f : TargetsRGBA ? (pixels[4 * i] + pixels[4 * i + 1] + pixels[4 * i + 2]) / 3.0f : pixels[i];
    if (covered) (*covered)[i] = c;
  }
  vtkOpenGLCheckErrorMacro("failed after ObscurancePass::ReadAO");
  return true;
}

std::size_t ObscurancePass::MemoryBytes() const {
  // Raw and filtered AO (1 or 4 floats) and view z (1 float) at the obscurance resolution.
  const std::size_t perPixel = 2 * (TargetsRGBA ? 16 : 4) + 4;
  return GBuffer->MemoryBytes() + static_cast<std::size_t>(TargetWidth) * TargetHeight * perPixel;
}

void ObscurancePass::ReleaseGraphicsResources(vtkWindow* w) {
  Superclass::ReleaseGraphicsResources(w);
  GBuffer->ReleaseGraphicsResources(w);
  ObscuranceStage->release();
  Filter->release();
  CombineStage->release();
  AOOutputStage->release();
  RawTarget = FilteredTarget = ZTarget = nullptr;
  Framebuffer = nullptr;
  TargetWidth = TargetHeight = 0;
  HasFrame = false;
}

}  // namespace aokit
