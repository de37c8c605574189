#include "fields/FieldPass.h"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkRenderState.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "FieldPassBoundsFS.h"
#include "FieldPassEval.h"
#include "FieldPassOccluderFS.h"
#include "FieldPassResolveFS.h"
#include "FieldPassSliceFS.h"
#include "FieldPassStartFS.h"
#include "fields/CapIntegralTable.h"
#include "fields/ConeTables.h"
#include "fields/FieldScreenRect.h"
#include "fields/HorizonLimit.h"
#include "render/FullScreenStage.h"
#include "render/Textures.h"

namespace aokit {

vtkStandardNewMacro(FieldPass);

namespace {

// Textures active (bound to units) while a stage draws.
class Bound {
 public:
  explicit Bound(std::initializer_list<vtkTextureObject*> textures) {
    for (vtkTextureObject* t : textures)
      if (t) {
        t->Activate();
        active_.push_back(t);
      }
  }
  ~Bound() {
    for (auto it = active_.rbegin(); it != active_.rend(); ++it) (*it)->Deactivate();
  }
  Bound(const Bound&) = delete;
  Bound& operator=(const Bound&) = delete;

 private:
  std::vector<vtkTextureObject*> active_;
};

std::string withEval(const char* stage, const std::string& eval) {
  std::string s = stage;
  vtkShaderProgram::Substitute(s, "//AOKIT::FieldEval", eval, false);
  return s;
}

int downsampleOf(double scale) { return scale >= 1.0 ? 1 : scale >= 0.5 ? 2 : 4; }

constexpr int kCullTile = 16;  // culling tile side, AO-target texels

void setSampler(vtkShaderProgram* p, const char* name, vtkTextureObject* t) {
  p->SetUniformi(name, t->GetTextureUnit());
}

}  // namespace

FieldPass::FieldPass()
    : EvalSource(FieldPassEval),
      OccluderSource(withEval(FieldPassOccluderFS, EvalSource)),
      SliceSource(withEval(FieldPassSliceFS, EvalSource)),
      BoundsStage(std::make_unique<FullScreenStage>("cull", FieldPassBoundsFS)),
      StartStage(std::make_unique<FullScreenStage>("fields (start)", FieldPassStartFS)),
      CubeStage(std::make_unique<FullScreenStage>("fields (cube occluders)", OccluderSource.c_str())),
      GridStage(std::make_unique<FullScreenStage>("fields (grid occluders)", OccluderSource.c_str())),
      ResolveStage(std::make_unique<FullScreenStage>("fields (resolve)", FieldPassResolveFS)),
      SliceStage(std::make_unique<FullScreenStage>("slice", SliceSource.c_str())) {
  FieldData = packFields({});
  OccluderData = packOccluders({}, {}, Settings.bias);
}

FieldPass::~FieldPass() = default;

void FieldPass::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  os << indent << "Fields: " << Fields.size() << " (" << FieldData.fieldBytes << " bytes), Occluders: "
     << Occluders.size() << "\n"
     << indent << "Combine: " << fieldCombineName(Settings.combine) << ", ResolutionScale: " << Settings.resolutionScale
     << ", View: " << fieldDebugViewName(Settings.view) << "\n";
}

void FieldPass::SetSettings(const FieldPassSettings& s) {
  validate(s);
  const bool biasChanged = s.bias != Settings.bias;
  Settings = s;
  if (biasChanged) {
    OccluderData = packOccluders(Fields, Occluders, Settings.bias);  // grid spheres grow with the bias
    OccludersDirty = true;
  }
  Modified();
}

void FieldPass::SetFields(std::vector<std::shared_ptr<const BakedField>> fields) {
  FieldGpuData data = packFields(fields);
  Fields = std::move(fields);
  FieldData = std::move(data);
  FieldsDirty = true;
  try {
    OccluderData = packOccluders(Fields, Occluders, Settings.bias);
  } catch (const std::invalid_argument&) {
    Occluders.clear();  // they named fields that are gone
    OccluderData = packOccluders(Fields, Occluders, Settings.bias);
  }
  OccludersDirty = true;
  Modified();
}

void FieldPass::SetOccluders(std::vector<FieldOccluder> occluders) {
  OccluderData = packOccluders(Fields, occluders, Settings.bias);
  Occluders = std::move(occluders);
  OccludersDirty = true;
  Modified();
}

void FieldPass::SetSceneRadius(double r) {
  if (!(r > 0.0) || r == SceneRadius) return;
  SceneRadius = r;
  Modified();
}

void FieldPass::SetBakedAO(bool on) {
  if (on == BakedAO) return;
  BakedAO = on;
  Modified();
}

DeferredConfig FieldPass::Configure(vtkRenderer*) {
  DeferredConfig c;
  c.bakedAO = BakedAO;
  c.downsample = downsampleOf(Settings.resolutionScale);
  c.aoChannels = 1;
  c.instanceIds = true;
  c.radius = SceneRadius;
  c.upsample.window = Settings.upsampleWindow;
  c.upsample.depthTolerance = Settings.depthTolerance;
  switch (Settings.view) {
    case FieldDebugView::AO:
    case FieldDebugView::Count: c.debugView = DeferredDebugView::AO; break;
    case FieldDebugView::Normals: c.debugView = DeferredDebugView::Normals; break;
    case FieldDebugView::Depth: c.debugView = DeferredDebugView::Depth; break;
    default: c.debugView = DeferredDebugView::None; break;
  }
  return c;
}

int FieldPass::Mode() const {
  if (Settings.view == FieldDebugView::Count) return 2;
  return Settings.combine == FieldCombine::Cone ? 1 : 0;
}

std::string FieldPass::Defines(int cubes, int grid) const {
  return "#define FIELD_CUBES " + std::to_string(cubes) +
         "\n#define FIELD_GRID " + std::to_string(grid) +
         "\n#define FIELD_MODE " + std::to_string(Mode()) +
         "\n#define FIELD_CONE " + std::to_string(Mode() == 1 ? 1 : 0) +
         "\n#define FIELD_GRID_NORMALIZED " + std::to_string(Settings.gridWeights == GridWeights::Normalized ? 1 : 0) +
         "\n#define FIELD_LUT_W " + std::to_string(CapIntegralTable::kWidth) +
         "\n#define FIELD_LUT_H " + std::to_string(CapIntegralTable::kHeight) +
         "\n#define FIELD_CLIP_N " + std::to_string(ClipTable::kSize) +
         "\n#define FIELD_MERGE_N " + std::to_string(MergeTable::kSize) +
         "\n#define FIELD_HORIZON_N " + std::to_string(HorizonTable::kSize) +
         "\n#define FIELD_DOWNSAMPLE " + std::to_string(downsampleOf(Settings.resolutionScale)) +
         "\n#define FIELD_TILE " + std::to_string(kCullTile) + "\n";
}

namespace {
int gridCode(const FieldGpuData& d) { return !d.hasGrid ? 0 : d.gridKind == FieldKind::Grid6 ? 1 : 2; }
}  // namespace

const char* FieldPass::ReadyFamily(const DeferredFrame& f) {
  const int grid = gridCode(FieldData);
  if (!BoundsStage->ready(f.renWin, Defines(0, 0))) return "cull";
  if (!StartStage->ready(f.renWin, Defines(0, 0))) return "fields (start)";
  if (FieldData.hasCube && !CubeStage->ready(f.renWin, Defines(1, 0))) return "fields (cube occluders)";
  if (grid && !GridStage->ready(f.renWin, Defines(0, grid))) return "fields (grid occluders)";
  if (Mode() == 1 && !ResolveStage->ready(f.renWin, Defines(0, 0))) return "fields (resolve)";
  if (Settings.view == FieldDebugView::Slice && !SliceStage->ready(f.renWin, Defines(FieldData.hasCube ? 1 : 0, grid)))
    return "slice";
  return nullptr;
}

bool FieldPass::Upload(vtkOpenGLRenderWindow* renWin) {
  GLint maxTexels = 0;
  glGetIntegerv(GL_MAX_TEXTURE_BUFFER_SIZE, &maxTexels);
  const std::size_t largest = std::max(FieldData.texels4.size() / 4, FieldData.texels3.size() / 3);
  if (largest > static_cast<std::size_t>(maxTexels)) {
    vtkErrorMacro("the fields need buffer textures of " << largest << " texels, this GL allows " << maxTexels
                                                       << "; showing the frame without AO");
    return false;
  }
  if (FieldsDirty) {
    Texels4 = makeBufferTexture(renWin, TexFormat::RGBA32F, FieldData.texels4.size() / 4, FieldData.texels4.data());
    Texels3 = makeBufferTexture(renWin, TexFormat::RGB32F, FieldData.texels3.size() / 3, FieldData.texels3.data());
    FieldInts = makeBufferTexture(renWin, TexFormat::RGBA32UI, FieldData.fieldInts.size() / 4, FieldData.fieldInts.data());
    FieldFloats = makeBufferTexture(renWin, TexFormat::RGBA32F, FieldData.fieldFloats.size() / 4, FieldData.fieldFloats.data());
    FieldsDirty = false;
  }
  if (OccludersDirty) {
    OccluderFloats = makeBufferTexture(renWin, TexFormat::RGBA32F, OccluderData.floats.size() / 4, OccluderData.floats.data());
    OccluderInts = makeBufferTexture(renWin, TexFormat::RGBA32UI, OccluderData.ints.size() / 4, OccluderData.ints.data());
    OccludersDirty = false;
  }
  UploadedBytes = (FieldData.texels4.size() + FieldData.texels3.size() + FieldData.fieldFloats.size() +
                   OccluderData.floats.size()) * sizeof(float) +
                  (FieldData.fieldInts.size() + OccluderData.ints.size()) * sizeof(std::uint32_t);
  if (!CapTable) {
    const CapIntegralTable& cap = capIntegralTable();
    CapTable = makeTexture2D(renWin, TexFormat::R32F, CapIntegralTable::kWidth, CapIntegralTable::kHeight,
                             cap.texels.data(), TexFilter::Linear);
    constexpr int h = aokit::HorizonTable::kSize;
    HorizonTable = makeTexture3D(renWin, TexFormat::R32F, h, h, h, horizonTable().texels.data(), TexFilter::Linear);
  }
  if (Mode() == 1 && !ClipTable) {  // the cone tables only where cones are merged
    const aokit::ClipTable& clip = clipTable();
    ClipTable = makeTexture2D(renWin, TexFormat::RG32F, aokit::ClipTable::kSize, aokit::ClipTable::kSize,
                              clip.texels.data(), TexFilter::Linear);
    const aokit::MergeTable& merge = mergeTable();
    constexpr int m = aokit::MergeTable::kSize;
    MergeTable = makeTexture3D(renWin, TexFormat::R32F, m, m, m, merge.texels.data(), TexFilter::Linear);
  }
  return true;
}

void FieldPass::BindFieldData(vtkShaderProgram* p) const {
  setSampler(p, "fieldTexels4", Texels4);
  setSampler(p, "fieldTexels3", Texels3);
  setSampler(p, "fieldInts", FieldInts);
  setSampler(p, "fieldFloats", FieldFloats);
  setSampler(p, "occluderFloats", OccluderFloats);
  setSampler(p, "occluderInts", OccluderInts);
  setSampler(p, "fieldCapLUT", CapTable);
  setSampler(p, "fieldHorizonLUT", HorizonTable);
  if (Mode() == 1) {
    setSampler(p, "fieldClipLUT", ClipTable);
    setSampler(p, "fieldMergeLUT", MergeTable);
  }
  p->SetUniformf("fieldInsideExponent", static_cast<float>(Settings.insideExponent));
  p->SetUniformf("fieldInsideOcclusion", static_cast<float>(Settings.insideOcclusion));
  p->SetUniformf("fieldBias", static_cast<float>(Settings.bias));
}

bool FieldPass::ReadTileDepths(DeferredFrame& f, TileDepths& tiles) {
  tiles.tile = kCullTile;
  tiles.tilesX = (f.targetWidth + kCullTile - 1) / kCullTile;
  tiles.tilesY = (f.targetHeight + kCullTile - 1) / kCullTile;
  if (!BoundsTarget) BoundsTarget = makeTexture2D(f.renWin, TexFormat::RG32F, tiles.tilesX, tiles.tilesY);
  else if (static_cast<int>(BoundsTarget->GetWidth()) != tiles.tilesX ||
           static_cast<int>(BoundsTarget->GetHeight()) != tiles.tilesY)
    BoundsTarget->Resize(tiles.tilesX, tiles.tilesY);
  vtkShaderProgram* p = BoundsStage->ready(f.renWin, Defines(0, 0));
  if (!p) return false;
  f.bindCommon(p);
  const int target[2] = {f.targetWidth, f.targetHeight}, count[2] = {tiles.tilesX, tiles.tilesY};
  p->SetUniform2i("fieldTarget", target);
  p->SetUniform2i("fieldTiles", count);
  BoundsStage->renderInto(f.fbo, {BoundsTarget});
  // A small read (8 bytes a tile); it waits for the G-buffer, which every later draw reads anyway.
  tiles.zRange.resize(2 * static_cast<std::size_t>(tiles.tilesX) * tiles.tilesY);
  f.state->PushReadFramebufferBinding();
  f.fbo->Bind(GL_READ_FRAMEBUFFER);
  f.fbo->AddColorAttachment(0, BoundsTarget);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, tiles.tilesX, tiles.tilesY, GL_RG, GL_FLOAT, tiles.zRange.data());
  f.fbo->RemoveColorAttachment(0);
  f.state->PopReadFramebufferBinding();
  return true;
}

vtkTextureObject* FieldPass::RenderAO(DeferredFrame& f) {
  if (!Upload(f.renWin) || !RenderOccluders(f)) return nullptr;
  f.mark("fields");
  LastFrame = f;
  return f.aoTarget;
}

namespace {

// Window depth of view z under the G-buffer's projection (DeferredCommon.glsl's aoViewZ inverted).
double windowDepth(const float depthToZ[4], double z) {
  const double w = depthToZ[2] * z + depthToZ[3];
  if (!(w > 0.0)) return 1.0;
  return std::clamp(0.5 * ((depthToZ[0] * z + depthToZ[1]) / w + 1.0), 0.0, 1.0);
}

void resize(vtkSmartPointer<vtkTextureObject>& t, vtkOpenGLRenderWindow* renWin, TexFormat format, int w, int h) {
  if (!t) t = makeTexture2D(renWin, format, w, h);
  else if (static_cast<int>(t->GetWidth()) != w || static_cast<int>(t->GetHeight()) != h) t->Resize(w, h);
}

}  // namespace

bool FieldPass::RenderOccluders(DeferredFrame& f) {
  TileDepths tiles;
  if (!ReadTileDepths(f, tiles)) return false;
  f.mark("cull");
  vtkOpenGLState* state = f.state;
  const int mode = Mode();
  const int target[2] = {f.targetWidth, f.targetHeight};
  if (mode == 1) {
    resize(StateTarget, f.renWin, TexFormat::RGBA32F, target[0], target[1]);
    glBindImageTexture(0, StateTarget->GetHandle(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  } else {
    StateTarget = nullptr;
  }
  if (!DepthStencil || static_cast<int>(DepthStencil->GetWidth()) != target[0] ||
      static_cast<int>(DepthStencil->GetHeight()) != target[1]) {
    DepthStencil = vtkSmartPointer<vtkTextureObject>::New();
    DepthStencil->SetContext(f.renWin);
    if (!DepthStencil->AllocateDepthStencil(target[0], target[1])) {
      vtkErrorMacro("could not allocate a depth-stencil target of " << target[0] << "x" << target[1]);
      return false;
    }
  }
  vtkTextureObject* ids = f.gbuffer->GetInstanceIdTexture();

  // Everything below draws into the AO target (and the z target) with the depth-stencil target.
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  vtkOpenGLState::ScopedglEnableDisable stencilTest(state, GL_STENCIL_TEST);
  GLfloat depthRange[2];
  glGetFloatv(GL_DEPTH_RANGE, depthRange);
  state->PushFramebufferBindings();
  f.fbo->Bind();
  f.fbo->AddColorAttachment(0, f.aoTarget);
  f.fbo->AddColorAttachment(1, f.zTarget);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, DepthStencil->GetHandle(), 0);
  f.fbo->ActivateDrawBuffers(2);
  f.fbo->Start(target[0], target[1]);  // viewport; blend, depth and scissor tests off
  auto finish = [&](bool ok) {
    glDepthRange(depthRange[0], depthRange[1]);
    state->vtkglStencilFunc(GL_ALWAYS, 0, 0xFF);
    state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    state->vtkglStencilMask(0xFF);
    state->vtkglDisable(GL_BLEND);
    state->vtkglDisable(GL_SCISSOR_TEST);
    state->vtkglDisable(GL_DEPTH_TEST);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, 0, 0);
    f.fbo->RemoveColorAttachments(2);
    state->PopFramebufferBindings();
    return ok;
  };

  // Start: occlusion 0, view z, the receivers' depth and instance ids (and no cone yet).
  vtkShaderProgram* p = StartStage->ready(f.renWin, Defines(0, 0));
  if (!p) return finish(false);
  {
    Bound inputs{ids};
    f.bindCommon(p);
    setSampler(p, "fieldIds", ids);
    p->SetUniform2i("fieldTarget", target);
    if (mode == 1) p->SetUniformi("fieldState", 0);
    state->vtkglEnable(GL_DEPTH_TEST);
    state->vtkglDepthFunc(GL_ALWAYS);
    state->vtkglDepthMask(GL_TRUE);
    state->vtkglEnable(GL_STENCIL_TEST);
    state->vtkglStencilFunc(GL_ALWAYS, 0, 0xFF);
    state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    state->vtkglStencilMask(0xFF);
    StartStage->render();
  }
  if (mode == 1) glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

  // One draw per occluder whose sphere reaches the screen, cube fields first.
  TargetGeometry geometry;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) geometry.clip[r][c] = f.clip[r][c];
  geometry.gbufferWidth = f.gbuffer->GetWidth();
  geometry.gbufferHeight = f.gbuffer->GetHeight();
  geometry.guardX = f.gbuffer->GetGuardX();
  geometry.guardY = f.gbuffer->GetGuardY();
  geometry.screenWidth = f.screenWidth;
  geometry.screenHeight = f.screenHeight;
  geometry.downsample = f.config.downsample;
  geometry.targetWidth = target[0];
  geometry.targetHeight = target[1];
  glm::dmat4 worldToView;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) worldToView[j][i] = f.worldToView[i * 4 + j];

  f.fbo->ActivateDrawBuffers(1);
  state->vtkglDepthFunc(GL_GREATER);  // the receiver is nearer than the sphere's far side
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  state->vtkglStencilMask(0);
  state->vtkglEnable(GL_SCISSOR_TEST);
  if (mode == 0) state->vtkglBlendFunc(GL_ONE_MINUS_DST_COLOR, GL_ONE);  // A + A_k - A A_k
  if (mode == 2) state->vtkglBlendFunc(GL_ONE, GL_ONE);                  // count
  if (mode != 1) state->vtkglEnable(GL_BLEND);
  DrawnOccluders = 0;
  DrawCalls = 0;
  DrawnTexels = 0;
  const int grid = gridCode(FieldData);
  for (int kindPass = 0; kindPass < 2; ++kindPass) {
    const int first = kindPass == 0 ? 0 : OccluderData.cubeCount;
    const int end = kindPass == 0 ? OccluderData.cubeCount : OccluderData.occluderCount;
    if (first == end) continue;
    FullScreenStage& stage = kindPass == 0 ? *CubeStage : *GridStage;
    p = stage.ready(f.renWin, kindPass == 0 ? Defines(1, 0) : Defines(0, grid));
    if (!p) return finish(false);
    Bound inputs{ids, Texels4, Texels3, CapTable, HorizonTable, mode == 1 ? ClipTable.Get() : nullptr,
                 mode == 1 ? MergeTable.Get() : nullptr};
    f.bindCommon(p);
    BindFieldData(p);
    setSampler(p, "fieldIds", ids);
    p->SetUniform2i("fieldTarget", target);
    if (mode == 1) p->SetUniformi("fieldState", 0);
    for (int k = first; k < end; ++k) {
      const float* o = &OccluderData.floats[static_cast<std::size_t>(k) * 16];
      const glm::dvec3 centre = glm::dvec3(worldToView * glm::dvec4(o[12], o[13], o[14], 1.0));
      const std::vector<TexelRect> runs = sphereTexelRuns(centre, o[15], geometry, tiles);
      if (runs.empty()) continue;
      const std::uint32_t owner = OccluderData.ints[static_cast<std::size_t>(k) * 4];
      const std::uint32_t field = OccluderData.ints[static_cast<std::size_t>(k) * 4 + 1];
      const int info[4] = {static_cast<int>(FieldData.fieldInts[field * 4]), static_cast<int>(FieldData.fieldInts[field * 4 + 1]),
                           static_cast<int>(FieldData.fieldInts[field * 4 + 2]),
                           static_cast<int>(FieldData.fieldInts[field * 4 + 3])};
      p->SetUniform4f("fieldM0", o);
      p->SetUniform4f("fieldM1", o + 4);
      p->SetUniform4f("fieldM2", o + 8);
      p->SetUniform4f("fieldSphere", o + 12);
      p->SetUniform1iv("fieldInfo", 4, info);
      const float* floats = &FieldData.fieldFloats[field * kFieldFloatsPerField];
      p->SetUniform4f("fieldF0", floats);
      p->SetUniform4f("fieldF1", floats + 4);
      p->SetUniform4f("fieldF2", floats + 8);
      p->SetUniformi("fieldOwner", static_cast<int>(owner));
      // The quad lies at the far side of the sphere (a little beyond, against rounding).
      const double far = windowDepth(f.depthToZ, centre.z - o[15] * 1.001 - 1e-6 * std::abs(centre.z));
      glDepthRange(far, far);
      // Receivers hold min(id, 255) >= 1: an owner the stencil cannot name compares against 0, which
      // passes them all (one test function for every draw: one llvmpipe shader variant).
      state->vtkglStencilFunc(GL_NOTEQUAL, owner >= 1 && owner <= 254 ? static_cast<int>(owner) : 0, 0xFF);
      for (const TexelRect& rect : runs) {
        state->vtkglScissor(rect.x0, rect.y0, rect.x1 - rect.x0 + 1, rect.y1 - rect.y0 + 1);
        stage.render();
        DrawnTexels += rect.area();
        ++DrawCalls;
      }
      if (mode == 1) glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);  // the next occluder reads these cones
      ++DrawnOccluders;
    }
  }
  finish(true);

  if (mode == 1) {  // cones: their occlusion into the AO target
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
    p = ResolveStage->ready(f.renWin, Defines(0, 0));
    if (!p) return false;
    Bound inputs{StateTarget};
    f.bindCommon(p);
    p->SetUniform2i("fieldTarget", target);
    setSampler(p, "fieldStateTex", StateTarget);
    ResolveStage->renderInto(f.fbo, {f.aoTarget});
  }
  return true;
}

void FieldPass::Render(const vtkRenderState* s) {
  Superclass::Render(s);
  if (Settings.view == FieldDebugView::Slice && LastFrame.gbuffer) RenderSlice(s);
}

void FieldPass::RenderSlice(const vtkRenderState* s) {
  vtkRenderer* r = s->GetRenderer();
  auto* renWin = static_cast<vtkOpenGLRenderWindow*>(r->GetRenderWindow());
  vtkOpenGLState* state = renWin->GetState();
  vtkShaderProgram* p = SliceStage->ready(renWin, Defines(FieldData.hasCube ? 1 : 0, gridCode(FieldData)));
  if (!p) return;
  vtkOpenGLState::ScopedglEnableDisable blend(state, GL_BLEND), depthTest(state, GL_DEPTH_TEST);
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  vtkOpenGLState::ScopedglViewport viewport(state);
  int x, y, w, h;
  r->GetTiledSizeAndOrigin(&w, &h, &x, &y);
  state->vtkglViewport(x, y, w, h);
  state->vtkglEnable(GL_BLEND);
  state->vtkglBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
  state->vtkglDisable(GL_DEPTH_TEST);
  GBufferPass* g = LastFrame.gbuffer;
  Bound inputs{g->GetDepthTexture(), g->GetNormalTexture(), g->GetColorTexture(), g->GetFlagsTexture(), Texels4,
               Texels3, FieldInts, FieldFloats, OccluderFloats, OccluderInts, CapTable, HorizonTable,
               Mode() == 1 ? ClipTable.Get() : nullptr,
               Mode() == 1 ? MergeTable.Get() : nullptr};
  LastFrame.bindCommon(p);
  BindFieldData(p);
  p->SetUniformi("fieldOccluders", OccluderData.occluderCount);
  p->SetUniformi("fieldCubes", OccluderData.cubeCount);
  p->SetUniformi("fieldSliceAxis", Settings.sliceAxis);
  p->SetUniformf("fieldSlicePosition", static_cast<float>(Settings.slicePosition));
  SliceStage->render();
}

std::size_t FieldPass::FamilyMemoryBytes() const {
  return UploadedBytes + textureBytes(CapTable) + textureBytes(HorizonTable) + textureBytes(ClipTable) +
         textureBytes(MergeTable) + textureBytes(StateTarget) + textureBytes(DepthStencil) + textureBytes(BoundsTarget);
}

void FieldPass::ReleaseFamily(vtkWindow* w) {
  BoundsStage->release(w);
  StartStage->release(w);
  CubeStage->release(w);
  GridStage->release(w);
  ResolveStage->release(w);
  SliceStage->release(w);
  Texels4 = Texels3 = FieldInts = FieldFloats = OccluderFloats = OccluderInts = nullptr;
  CapTable = HorizonTable = ClipTable = MergeTable = nullptr;
  StateTarget = DepthStencil = BoundsTarget = nullptr;
  UploadedBytes = 0;
  FieldsDirty = OccludersDirty = true;
  LastFrame = DeferredFrame{};
}

}  // namespace aokit
