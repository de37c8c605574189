#include "voxel/HybridPass.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <vtkObjectFactory.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "HybridMarchFS.h"
#include "HybridVoxelViewFS.h"
#include "render/DrawBuffers.h"
#include "render/FullScreenStage.h"

namespace aokit {

vtkStandardNewMacro(HybridPass);

HybridPass::HybridPass()
    : MarchStage(std::make_unique<FullScreenStage>("march", HybridMarchFS)),
      VoxelViewStage(std::make_unique<FullScreenStage>("voxel view", HybridVoxelViewFS)) {}

HybridPass::~HybridPass() { ReleaseOnDestroy(); }

void HybridPass::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  hybridSchema().print(os, Settings, indent);
}

void HybridPass::SetSettings(const HybridSettings& s) {
  validate(s);
  Settings = s;
  Voxels.invalidate();
  Modified();
}

std::string HybridPass::MarchDefines(const FrameContext& context) const {
  return hybridMarchShape(Settings, context.falloff).defines();
}

void HybridPass::Plan(const FrameContext& context, DeferredPlan& plan) {
  plan.config.bakedAO = Settings.staticBake;
  Voxels.plan(plan, plan.renWin, Settings);
  plan.stage(*MarchStage, MarchDefines(context));
  if (Settings.common.view == DebugView::Voxels) {
    plan.stage(*VoxelViewStage, "");
    plan.overlay = true;
  }
}

int raysPerMarchPass(const HybridMarchConstants& c, bool hasGrid) {
  if (!hasGrid) return c.rays;
  // Loop iterations of one ray, at most: each step, and the span test's words in it (a step spans
  // at most its length in voxels plus one along the grid's depth, and no more than the column).
  // The segment test: each column of the walk and its run's words beyond the first (all runs
  // together span the ray's depth plus one voxel a column), then the first set voxel's words.
  const glm::mat3 m3(c.worldToGrid);
  const double voxelsPerUnit = std::sqrt(std::max({glm::dot(m3[0], m3[0]), glm::dot(m3[1], m3[1]), glm::dot(m3[2], m3[2])}));
  const auto runWords = [&](double voxels) { return std::min(c.dims.z / 32.0 + 1.0, std::ceil((voxels + 1.0) / 32.0) + 1.0); };
  const double stepWords = runWords(c.radius / c.steps * voxelsPerUnit), rayWords = runWords(c.radius * voxelsPerUnit);
  const double perRay = c.segmentWalk() ? 2.0 + 3.0 * c.walkColumns + 2.0 * rayWords : 2.0 + c.steps * (1.0 + stepWords);
  // llvmpipe's 65535 iterations, less the denominator's loop over all rays and some margin.
  const double budget = 60000.0 - 2.0 * c.rays;
  return static_cast<int>(std::clamp(std::floor(budget / perRay), 1.0, static_cast<double>(c.rays)));
}

vtkTextureObject* HybridPass::RenderAO(DeferredFrame& f) {
  // llvmpipe runs a compute dispatch at once on the calling thread, while timestamp queries are
  // written when its rasterizer reaches them in a deferred scene: without a finish on both sides
  // the voxelization would fall between two timestamps of the same scene and read as ~0 ms.
  const bool timing = f.timer && f.timer->enabled();
  if (timing) glFinish();
  try {
    Voxels.voxelize(f.renderer, f.renWin, Settings, f.context);
  } catch (const std::exception& e) {
    // Only what settings cannot rule out beforehand: a degenerate camera, a grid past this
    // context's texture size. The frame is shown without AO.
    vtkErrorMacro("hybrid: " << e.what());
    return nullptr;
  }
  f.mark("voxelize");
  if (timing) glFinish();

  vtkShaderProgram* p = MarchStage->use(f.renWin);
  if (!p) return nullptr;
  const HybridMarchConstants& c = Voxels.constants();
  f.bindCommon(p);
  Voxels.bind(p, f.renWin, Settings.staticBake);
  p->SetUniformf("haoRadius", c.radius);
  p->SetUniformi("haoSteps", c.steps);
  p->SetUniformi("haoWalkColumns", c.walkColumns);
  p->SetUniformf("haoCosMax", c.cosMax);
  p->SetUniformf("haoNormalOffset", c.normalOffset);
  p->SetUniformf("haoReach", c.reach);
  p->SetUniformf("haoInvCell", c.invJitterCell);
  // A still frame of a running mean draws new jitter: the seed mixed with the frame's index.
  const std::uint32_t seed = f.accumulated == 0 ? c.jitterSeed : c.jitterSeed ^ (0x9E3779B9u * static_cast<std::uint32_t>(f.accumulated));
  p->SetUniformi("haoSeedBits", static_cast<int>(seed));
  p->SetUniformi("haoDownsample", f.config.downsample);
  const int target[2] = {f.targetWidth, f.targetHeight};
  p->SetUniform2i("haoTargetSize", target);
  // Rays per pass within llvmpipe's loop budget (HybridMarchFS.glsl); the first pass writes AO and
  // z, later ones add their part of the AO.
  const int perPass = raysPerMarchPass(c, Voxels.hasGrid());
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(f.state);
  for (int first = 0; first < c.rays; first += perPass) {
    p->SetUniformi("haoFirstRay", first);
    p->SetUniformi("haoRayEnd", std::min(c.rays, first + perPass));
    if (first == 0) {
      MarchStage->renderInto(f.fbo, {f.aoTarget, f.zTarget});
    } else {
      // As FullScreenStage::renderInto, whose framebuffer start switches blending off.
      f.state->PushFramebufferBindings();
      f.fbo->Bind();
      f.fbo->AddColorAttachment(0, f.aoTarget);
      activateDrawBuffers(f.fbo, 1);
      f.fbo->Start(f.targetWidth, f.targetHeight);
      f.state->vtkglEnable(GL_BLEND);
      f.state->vtkglBlendFunc(GL_ONE, GL_ONE);
      MarchStage->render();
      f.state->vtkglDisable(GL_BLEND);
      f.fbo->RemoveColorAttachments(1);
      f.state->PopFramebufferBindings();
    }
  }
  Voxels.unbind(Settings.staticBake);
  f.mark("march");
  return f.aoTarget;
}

void HybridPass::RenderOverlay(DeferredFrame& f) {
  vtkShaderProgram* v = VoxelViewStage->use(f.renWin);
  if (!v) return;
  f.bindCommon(v);
  Voxels.bind(v, f.renWin, false);
  VoxelViewStage->render();
  Voxels.unbind(false);
}

void HybridPass::ReleaseFamily(vtkWindow* w) {
  if (auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(w)) renWin->MakeCurrent();
  Voxels.release(w);
  MarchStage->release(w);
  VoxelViewStage->release(w);
}

}  // namespace aokit
