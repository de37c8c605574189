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
#include "render/ActorKeys.h"
#include "render/FullScreenStage.h"
#include "render/Textures.h"
#include "voxel/GpuVoxelizer.h"
#include "voxel/VoxelGrid.h"

namespace aokit {

vtkStandardNewMacro(HybridPass);

VoxelizeMethod voxelizeMethodFor(VoxelizingFrame frame) {
  switch (frame) {
    case VoxelizingFrame::Rotated: return VoxelizeMethod::ColumnCentre;
    case VoxelizingFrame::DominantAxis: return VoxelizeMethod::DominantCentre;
    case VoxelizingFrame::ThreeAxis: break;
  }
  return VoxelizeMethod::ThreeAxis;
}

HybridPass::HybridPass()
    : Voxelizer(std::make_unique<GpuVoxelizer>()),
      StaticVoxelizer(std::make_unique<GpuVoxelizer>()),
      MarchStage(std::make_unique<FullScreenStage>("march", HybridMarchFS)),
      VoxelViewStage(std::make_unique<FullScreenStage>("voxel view", HybridVoxelViewFS)) {}

HybridPass::~HybridPass() = default;

void HybridPass::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  os << indent << "GridResolution: " << Settings.gridResolution << ", Rays: " << Settings.rays
     << ", Steps: " << Settings.steps << ", Scale: 1/" << static_cast<int>(Settings.scale)
     << ", FilterSize: " << Settings.filterSize << "\n"
     << indent << "Radius: " << Settings.radius << " (scene " << SceneRadius << ")\n"
     << indent << "StaticBake: " << (Settings.staticBake ? "on" : "off") << "\n";
}

void HybridPass::SetSettings(const HybridSettings& s) {
  validate(s);
  Settings = s;
  Regions.clear();
  Plans.clear();
  Modified();
}

void HybridPass::SetSceneRadius(double r) {
  if (r == SceneRadius) return;
  SceneRadius = r;
  Modified();
}

void HybridPass::SetSceneFalloff(Falloff f) {
  if (f == SceneFalloff) return;
  SceneFalloff = f;
  Modified();
}

double HybridPass::ResolvedRadius(vtkRenderer* r) const {
  if (Settings.radius > 0.0) return Settings.radius;
  if (SceneRadius > 0.0) return SceneRadius;
  // A plain VTK scene: size the radius from what is visible.
  double b[6];
  r->ComputeVisiblePropBounds(b);
  const double diag = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
                                (b[5] - b[4]) * (b[5] - b[4]));
  return (b[0] <= b[1] && std::isfinite(diag) && diag > 0.0) ? 0.1 * diag : 1.0;
}

DeferredConfig HybridPass::Configure(vtkRenderer* renderer) {
  Radius = ResolvedRadius(renderer);
  const bool voxels = Settings.view == HybridView::Voxels;
  DeferredConfig c;
  c.downsample = voxels ? 1 : static_cast<int>(Settings.scale);
  c.aoChannels = 1;
  c.bakedAO = StaticMode();
  c.radius = Radius;
  // The CPU oracle's m = max(1, filterSize): 1 is each pixel's own texel.
  c.upsample.window = voxels ? 0 : std::max(1, Settings.filterSize);
  c.upsample.positionRadius = Settings.positionSupport * Radius;
  c.upsample.normalSupport = Settings.normalSupport;
  c.upsample.normalKernel = true;
  c.upsample.aoRange = Settings.aoSupport;
  switch (Settings.view) {
    case HybridView::None: c.debugView = DeferredDebugView::None; break;
    case HybridView::AO: c.debugView = DeferredDebugView::AO; break;
    case HybridView::Normals: c.debugView = DeferredDebugView::Normals; break;
    case HybridView::Depth: c.debugView = DeferredDebugView::Depth; break;
    case HybridView::Voxels: c.debugView = DeferredDebugView::Result; break;
  }
  return c;
}

std::string HybridPass::MarchDefines() const {
  HybridMarchConstants c;
  c.rays = Settings.rays;
  c.steps = Settings.steps;
  c.falloff = Settings.falloff.value_or(SceneFalloff);
  c.spanTest = Settings.spanTest;
  c.staticDynamic = StaticMode();
  return c.defines();
}

const char* HybridPass::ReadyFamily(const DeferredFrame& f) {
  if (const char* failed = Voxelizer->ready(f.renWin, voxelizeMethodFor(Settings.frame), Settings.solid)) return failed;
  if (StaticMode())
    if (const char* failed = StaticVoxelizer->ready(f.renWin, voxelizeMethodFor(Settings.frame), Settings.solid))
      return failed;
  if (!MarchStage->ready(f.renWin, MarchDefines())) return "march";
  if (Settings.view == HybridView::Voxels && !VoxelViewStage->ready(f.renWin, "")) return "voxel view";
  return nullptr;
}

void HybridPass::Voxelize(DeferredFrame& f) {
  const FrameCasters casters = gatherCasters(f.renderer);
  VoxelizedCasters = VoxelizedStatic = 0;
  HasGrid = false;
  Constants.rays = Settings.rays;  // the march still runs (AO 0): its pass count needs these
  Constants.steps = Settings.steps;
  if (StaticMode()) {
    VoxelizeStaticDynamic(f, casters);
    return;
  }
  Region = Regions.get(frameView(f.renderer), casters.bounds, Radius, Settings);
  if (!Region.empty) {
    std::vector<CasterDraw> draws;
    for (std::size_t i : Region.casters)
      if (const CasterMesh* mesh = Buffers.get(casters.polys[i]))
        draws.push_back({mesh, CasterBuffers::propMatrix(casters.props[i])});
    Voxelizer->voxelize(f.renWin, Region.frame, draws, voxelizeMethodFor(Settings.frame), Settings.solid);
    Constants = makeHybridMarchConstants(Settings, Radius, SceneFalloff, Region.frame);
    VoxelizedCasters = draws.size();
    HasGrid = true;
  }
  Buffers.sweep();  // meshes no caster showed this frame
}

void HybridPass::VoxelizeStaticDynamic(DeferredFrame& f, const FrameCasters& casters) {
  const StaticDynamicPlan& plan = Plans.get(frameView(f.renderer), casters.bounds, staticFlags(casters), Radius, Settings);
  Region = plan.region;
  Zones = plan.zones;
  if (!plan.empty) {
    auto drawsOf = [&](const std::vector<std::size_t>& which) {
      std::vector<CasterDraw> draws;
      for (std::size_t i : which)
        if (const CasterMesh* mesh = Buffers.get(casters.polys[i]))
          draws.push_back({mesh, CasterBuffers::propMatrix(casters.props[i])});
      return draws;
    };
    const std::vector<CasterDraw> dynamicDraws = drawsOf(plan.dynamicCasters), staticDraws = drawsOf(plan.staticCasters);
    const VoxelizeMethod method = voxelizeMethodFor(Settings.frame);
    Voxelizer->voxelize(f.renWin, Region.frame, dynamicDraws, method, Settings.solid);
    StaticVoxelizer->voxelize(f.renWin, Region.frame, staticDraws, method, Settings.solid);
    Constants = makeHybridMarchConstants(Settings, Radius, SceneFalloff, Region.frame);
    VoxelizedCasters = dynamicDraws.size() + staticDraws.size();
    VoxelizedStatic = staticDraws.size();
    HasGrid = true;
  }
  Buffers.sweep();
}

void HybridPass::BindGrid(vtkShaderProgram* p, const DeferredFrame& f) {
  vtkTextureObject* grid = HasGrid ? Voxelizer->grid() : nullptr;
  if (!grid) {
    if (!EmptyGrid) {
      const unsigned zeros[4] = {0, 0, 0, 0};
      EmptyGrid = makeTexture2D(f.renWin, TexFormat::R32UI, 4, 1, zeros);
    }
    grid = EmptyGrid;
  }
  grid->Activate();
  p->SetUniformi("haoGrid", grid->GetTextureUnit());
  p->SetUniformi("haoEmpty", HasGrid ? 0 : 1);
  if (StaticMode() && p->IsUniformUsed("haoStaticGrid")) {
    vtkTextureObject* statics = HasGrid ? StaticVoxelizer->grid() : nullptr;
    if (!statics) statics = EmptyGrid;
    statics->Activate();
    p->SetUniformi("haoStaticGrid", statics->GetTextureUnit());
  }
  if (StaticMode() && p->IsUniformUsed("haoZoneCount")) {
    float lo[kMaxDynamicZones][3] = {}, hi[kMaxDynamicZones][3] = {};
    const int count = HasGrid ? static_cast<int>(std::min<std::size_t>(Zones.size(), kMaxDynamicZones)) : 0;
    for (int z = 0; z < count; ++z)
      for (int a = 0; a < 3; ++a) {
        lo[z][a] = static_cast<float>(Zones[z].min[a]);
        hi[z][a] = static_cast<float>(Zones[z].max[a]);
      }
    p->SetUniformi("haoZoneCount", count);
    p->SetUniform3fv("haoZoneMin", kMaxDynamicZones, lo);
    p->SetUniform3fv("haoZoneMax", kMaxDynamicZones, hi);
  }
  const int dims[3] = {Constants.dims.x, Constants.dims.y, Constants.dims.z};
  p->SetUniform1iv("haoDimsV", 3, dims);
  glm::mat4 m = Constants.worldToGrid;
  p->SetUniformMatrix4x4("haoWorldToGrid", &m[0][0]);
}

int raysPerMarchPass(const HybridMarchConstants& c, bool hasGrid) {
  if (!hasGrid) return c.rays;
  // Loop iterations of one ray, at most: each step, and the span test's words in it (a step spans
  // at most its length in voxels plus one along the grid's depth, and no more than the column).
  const glm::mat3 m3(c.worldToGrid);
  const double voxelsPerUnit = std::sqrt(std::max({glm::dot(m3[0], m3[0]), glm::dot(m3[1], m3[1]), glm::dot(m3[2], m3[2])}));
  const double stepVoxels = c.radius / c.steps * voxelsPerUnit;
  const double words = std::min(c.dims.z / 32.0 + 1.0, std::ceil((stepVoxels + 1.0) / 32.0) + 1.0);
  const double perRay = 2.0 + c.steps * (1.0 + words);
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
    Voxelize(f);
  } catch (const std::exception& e) {
    // Only what settings cannot rule out beforehand: a degenerate camera, a grid past this
    // context's texture size. The frame is shown without AO.
    vtkErrorMacro("hybrid: " << e.what());
    return nullptr;
  }
  f.mark("voxelize");
  if (timing) glFinish();

  vtkShaderProgram* p = MarchStage->ready(f.renWin, MarchDefines());
  if (!p) return nullptr;
  f.bindCommon(p);
  BindGrid(p, f);
  p->SetUniformf("haoRadius", Constants.radius);
  p->SetUniformf("haoCosMax", Constants.cosMax);
  p->SetUniformf("haoNormalOffset", Constants.normalOffset);
  p->SetUniformf("haoInvCell", Constants.invJitterCell);
  p->SetUniformi("haoSeedBits", static_cast<int>(Constants.jitterSeed));
  p->SetUniformi("haoDownsample", f.config.downsample);
  const int target[2] = {f.targetWidth, f.targetHeight};
  p->SetUniform2i("haoTargetSize", target);
  // Rays per pass within llvmpipe's loop budget (HybridMarchFS.glsl); the first pass writes AO and
  // z, later ones add their part of the AO.
  const int perPass = raysPerMarchPass(Constants, HasGrid);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(f.state);
  for (int first = 0; first < Constants.rays; first += perPass) {
    p->SetUniformi("haoFirstRay", first);
    p->SetUniformi("haoRayEnd", std::min(Constants.rays, first + perPass));
    if (first == 0) {
      MarchStage->renderInto(f.fbo, {f.aoTarget, f.zTarget});
    } else {
      // As FullScreenStage::renderInto, whose framebuffer start switches blending off.
      f.state->PushFramebufferBindings();
      f.fbo->Bind();
      f.fbo->AddColorAttachment(0, f.aoTarget);
      f.fbo->ActivateDrawBuffers(1);
      f.fbo->Start(f.targetWidth, f.targetHeight);
      f.state->vtkglEnable(GL_BLEND);
      f.state->vtkglBlendFunc(GL_ONE, GL_ONE);
      MarchStage->render();
      f.state->vtkglDisable(GL_BLEND);
      f.fbo->RemoveColorAttachments(1);
      f.state->PopFramebufferBindings();
    }
  }
  UnbindGrid();
  f.mark("march");

  if (Settings.view == HybridView::Voxels) {
    vtkShaderProgram* v = VoxelViewStage->ready(f.renWin, "");
    if (!v) return nullptr;
    f.bindCommon(v);
    BindGrid(v, f);
    VoxelViewStage->renderInto(f.fbo, {f.aoTarget});
    UnbindGrid();
  }
  return f.aoTarget;
}

void HybridPass::UnbindGrid() {
  vtkTextureObject* grid = HasGrid ? Voxelizer->grid() : nullptr;
  (grid ? grid : EmptyGrid.Get())->Deactivate();
  if (!StaticMode()) return;
  vtkTextureObject* statics = HasGrid ? StaticVoxelizer->grid() : nullptr;
  statics = statics ? statics : EmptyGrid.Get();
  if (statics != grid) statics->Deactivate();
}

bool HybridPass::ReadGrid(vtkOpenGLRenderWindow* renWin, VoxelGrid& out) {
  if (!HasGrid) return false;
  renWin->MakeCurrent();
  return Voxelizer->readBack(out);
}

std::size_t HybridPass::FamilyMemoryBytes() const {
  return Voxelizer->memoryBytes() + StaticVoxelizer->memoryBytes() + Buffers.memoryBytes() + textureBytes(EmptyGrid);
}

void HybridPass::ReleaseFamily(vtkWindow* w) {
  if (auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(w)) renWin->MakeCurrent();
  Voxelizer->release(w);
  StaticVoxelizer->release(w);
  Buffers.release();
  MarchStage->release(w);
  VoxelViewStage->release(w);
  if (EmptyGrid) EmptyGrid->ReleaseGraphicsResources(w);
  EmptyGrid = nullptr;
  Regions.clear();
  Plans.clear();
  HasGrid = false;
  Region = VoxelRegion{};
  Zones.clear();
}

}  // namespace aokit
