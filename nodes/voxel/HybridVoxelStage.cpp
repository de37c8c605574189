#include "voxel/HybridVoxelStage.h"

#include <algorithm>

#include <vtkOpenGLRenderWindow.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>

#include "render/Textures.h"
#include "voxel/GpuVoxelizer.h"
#include "voxel/VoxelGrid.h"

namespace aokit {

VoxelizeMethod voxelizeMethodFor(VoxelizingFrame frame) {
  switch (frame) {
    case VoxelizingFrame::Rotated: return VoxelizeMethod::ColumnCentre;
    case VoxelizingFrame::DominantAxis: return VoxelizeMethod::DominantCentre;
    case VoxelizingFrame::ThreeAxis: break;
  }
  return VoxelizeMethod::ThreeAxis;
}

HybridVoxelStage::HybridVoxelStage()
    : voxelizer_(std::make_unique<GpuVoxelizer>()), staticVoxelizer_(std::make_unique<GpuVoxelizer>()) {}

HybridVoxelStage::~HybridVoxelStage() = default;

void HybridVoxelStage::plan(DeferredPlan& plan, vtkOpenGLRenderWindow* renWin, const HybridSettings& s) {
  const VoxelizeMethod method = voxelizeMethodFor(s.frame);
  plan.program("voxelize", [this, renWin, method, solid = s.solid, trim = s.trimShell] {
    return voxelizer_->ready(renWin, method, solid, trim) == nullptr;
  });
  if (s.staticBake)
    plan.program("voxelize (static)", [this, renWin, method, solid = s.solid, trim = s.trimShell] {
      return staticVoxelizer_->ready(renWin, method, solid, trim) == nullptr;
    });
}

void HybridVoxelStage::invalidate() {
  regions_.clear();
  plans_.clear();
}

std::vector<CasterDraw> HybridVoxelStage::draws(const FrameCasters& casters, const std::vector<std::size_t>& which) {
  std::vector<CasterDraw> out;
  for (std::size_t i : which)
    if (const CasterMesh* mesh = buffers_.get(casters.polys[i]))
      out.push_back({mesh, casters.matrices[i]});
  return out;
}

void HybridVoxelStage::voxelize(vtkRenderer* renderer, vtkOpenGLRenderWindow* renWin, const HybridSettings& s,
                                FrameContext& context) {
  const FrameCasters casters = gatherCasters(renderer, meshes_, context.ranks);
  context.exchangedBytes += meshes_.exchangedBytes();
  voxelized_ = voxelizedStatic_ = 0;
  hasGrid_ = false;
  constants_.rays = s.rays;  // the march still runs (AO 0): its pass count needs these
  constants_.steps = s.steps;
  if (s.staticBake) {
    voxelizeStaticDynamic(renderer, renWin, s, context, casters);
  } else {
    region_ = regions_.get(frameView(renderer, context.ranks), casters.bounds, context.radius, s);
    if (!region_.empty) {
      const std::vector<CasterDraw> d = draws(casters, region_.casters);
      voxelizer_->voxelize(renWin, region_.frame, d, voxelizeMethodFor(s.frame), s.solid, s.trimShell);
      constants_ = makeHybridMarchConstants(s, context, region_.frame);
      voxelized_ = d.size();
      hasGrid_ = true;
    }
  }
  buffers_.sweep();  // meshes no caster showed this frame
}

void HybridVoxelStage::voxelizeStaticDynamic(vtkRenderer* renderer, vtkOpenGLRenderWindow* renWin,
                                             const HybridSettings& s, const FrameContext& context,
                                             const FrameCasters& casters) {
  const StaticDynamicPlan& plan =
      plans_.get(frameView(renderer, context.ranks), casters.bounds, staticFlags(casters), context.radius, s);
  region_ = plan.region;
  zones_ = plan.zones;
  if (plan.empty) return;
  const std::vector<CasterDraw> dynamicDraws = draws(casters, plan.dynamicCasters);
  const std::vector<CasterDraw> staticDraws = draws(casters, plan.staticCasters);
  const VoxelizeMethod method = voxelizeMethodFor(s.frame);
  voxelizer_->voxelize(renWin, region_.frame, dynamicDraws, method, s.solid, s.trimShell);
  staticVoxelizer_->voxelize(renWin, region_.frame, staticDraws, method, s.solid, s.trimShell);
  constants_ = makeHybridMarchConstants(s, context, region_.frame);
  voxelized_ = dynamicDraws.size() + staticDraws.size();
  voxelizedStatic_ = staticDraws.size();
  hasGrid_ = true;
}

void HybridVoxelStage::bind(vtkShaderProgram* p, vtkOpenGLRenderWindow* renWin, bool staticMode) {
  vtkTextureObject* grid = hasGrid_ ? voxelizer_->grid() : nullptr;
  if (!grid) {
    if (!emptyGrid_) {
      const unsigned zeros[4] = {0, 0, 0, 0};
      emptyGrid_ = makeTexture2D(renWin, TexFormat::R32UI, 4, 1, zeros);
    }
    grid = emptyGrid_;
  }
  grid->Activate();
  p->SetUniformi("haoGrid", grid->GetTextureUnit());
  p->SetUniformi("haoEmpty", hasGrid_ ? 0 : 1);
  if (staticMode && p->IsUniformUsed("haoStaticGrid")) {
    vtkTextureObject* statics = hasGrid_ ? staticVoxelizer_->grid() : nullptr;
    if (!statics) statics = emptyGrid_;
    statics->Activate();
    p->SetUniformi("haoStaticGrid", statics->GetTextureUnit());
  }
  if (staticMode && p->IsUniformUsed("haoZoneCount")) {
    float lo[kMaxDynamicZones][3] = {}, hi[kMaxDynamicZones][3] = {};
    const int count = hasGrid_ ? static_cast<int>(std::min<std::size_t>(zones_.size(), kMaxDynamicZones)) : 0;
    for (int z = 0; z < count; ++z)
      for (int a = 0; a < 3; ++a) {
        lo[z][a] = static_cast<float>(zones_[z].min[a]);
        hi[z][a] = static_cast<float>(zones_[z].max[a]);
      }
    p->SetUniformi("haoZoneCount", count);
    p->SetUniform3fv("haoZoneMin", kMaxDynamicZones, lo);
    p->SetUniform3fv("haoZoneMax", kMaxDynamicZones, hi);
  }
  const int dims[3] = {constants_.dims.x, constants_.dims.y, constants_.dims.z};
  p->SetUniform1iv("haoDimsV", 3, dims);
  glm::mat4 m = constants_.worldToGrid;
  p->SetUniformMatrix4x4("haoWorldToGrid", &m[0][0]);
}

void HybridVoxelStage::unbind(bool staticMode) {
  vtkTextureObject* grid = hasGrid_ ? voxelizer_->grid() : nullptr;
  (grid ? grid : emptyGrid_.Get())->Deactivate();
  if (!staticMode) return;
  vtkTextureObject* statics = hasGrid_ ? staticVoxelizer_->grid() : nullptr;
  statics = statics ? statics : emptyGrid_.Get();
  if (statics != grid) statics->Deactivate();
}

bool HybridVoxelStage::readGrid(vtkOpenGLRenderWindow* renWin, VoxelGrid& out) {
  if (!hasGrid_) return false;
  renWin->MakeCurrent();
  return voxelizer_->readBack(out);
}

std::size_t HybridVoxelStage::memoryBytes() const {
  return voxelizer_->memoryBytes() + staticVoxelizer_->memoryBytes() + buffers_.memoryBytes() + textureBytes(emptyGrid_);
}

void HybridVoxelStage::release(vtkWindow* w) {
  voxelizer_->release(w);
  staticVoxelizer_->release(w);
  buffers_.release();
  if (emptyGrid_) emptyGrid_->ReleaseGraphicsResources(w);
  emptyGrid_ = nullptr;
  invalidate();
  hasGrid_ = false;
  region_ = VoxelRegion{};
  zones_.clear();
}

}  // namespace aokit
