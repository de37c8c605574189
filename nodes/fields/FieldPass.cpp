#include "fields/FieldPass.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include <vtkCommand.h>

#include <vtkObjectFactory.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLState.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include "FieldPassOccluderFS.h"
#include "FieldPassResolveFS.h"
#include "FieldPassStartFS.h"
#include "render/DrawBuffers.h"
#include "render/GBufferPass.h"
#include "render/Textures.h"

namespace aokit {

vtkStandardNewMacro(FieldPass);

namespace {

int gridCode(const FieldGpuData& d) { return !d.hasGrid ? 0 : d.gridKind == FieldKind::Grid6 ? 1 : 2; }

// Window depth of view z under the G-buffer's projection (DeferredCommon.glsl's aoViewZ inverted).
double windowDepth(const float depthToZ[4], double z) {
  const double w = depthToZ[2] * z + depthToZ[3];
  if (!(w > 0.0)) return 1.0;
  return std::clamp(0.5 * ((depthToZ[0] * z + depthToZ[1]) / w + 1.0), 0.0, 1.0);
}

}  // namespace

FieldPass::FieldPass()
    : OccluderSource(withFieldEval(FieldPassOccluderFS)),
      StartStage(std::make_unique<FullScreenStage>("fields (start)", FieldPassStartFS)),
      CubeStage(std::make_unique<FullScreenStage>("fields (cube occluders)", OccluderSource.c_str())),
      GridStage(std::make_unique<FullScreenStage>("fields (grid occluders)", OccluderSource.c_str())),
      ResolveStage(std::make_unique<FullScreenStage>("fields (resolve)", FieldPassResolveFS)) {
  FieldData = packFields({});
  OccluderData = packOccluders({}, {}, Settings.eval.bias);
}

FieldPass::~FieldPass() { ReleaseOnDestroy(); }

void FieldPass::PrintSelf(ostream& os, vtkIndent indent) {
  Superclass::PrintSelf(os, indent);
  os << indent << "Fields: " << Fields.size() << " (" << FieldData.fieldBytes << " bytes), Occluders: "
     << Occluders.size() << "\n";
  fieldSchema().print(os, Settings, indent);
}

void FieldPass::SetSettings(const FieldSettings& s) {
  validate(s);
  const bool biasChanged = s.eval.bias != Settings.eval.bias;
  std::ostringstream before, after;
  fieldSchema().print(before, Settings, vtkIndent());
  fieldSchema().print(after, s, vtkIndent());
  if (Found && before.str() != after.str()) Found->clear();  // bakes may differ: obtained again (the cache keeps them)
  Settings = s;
  if (biasChanged) {
    OccluderData = packOccluders(Fields, Occluders, Settings.eval.bias);  // grid spheres grow with the bias
    Textures.occludersChanged();
  }
  Modified();
}

void FieldPass::SetFields(std::vector<std::shared_ptr<const BakedField>> fields) {
  FindOccluders = false;
  UseFields(std::move(fields));
}

void FieldPass::SetOccluders(std::vector<FieldOccluder> occluders) {
  FindOccluders = false;
  UseOccluders(std::move(occluders));
}

void FieldPass::SetFindOccluders(bool on) {
  if (on == FindOccluders) return;
  FindOccluders = on;
  Modified();
}

const FieldPrepareReport& FieldPass::GetFoundReport() const {
  static const FieldPrepareReport none;
  return Found ? Found->report() : none;
}

void FieldPass::PrepareFrame(vtkRenderer* renderer, FrameContext& context) {
  if (!FindOccluders) return;
  if (!Found) Found = std::make_unique<PropOccluders>();
  if (RadiusIsGiven()) HeldRadius = 0.0;
  else if (HeldRadius > 0.0) context.radius = HeldRadius;
  else HeldRadius = context.radius;
  bool started = false;
  auto progress = [&](double f) {
    if (!started) InvokeEvent(vtkCommand::StartEvent);
    started = true;
    InvokeEvent(vtkCommand::ProgressEvent, &f);
  };
  const bool replanned = Found->update(renderer, Settings, context.radius, context.falloff, progress, context.ranks);
  context.exchangedBytes += Found->exchangedBytes();
  if (started) InvokeEvent(vtkCommand::EndEvent);
  if (replanned) {
    Occluders.clear();
    UseFields(Found->fields());
  }
  const std::vector<FieldOccluder>& now = Found->occluders();
  auto same = [](const FieldOccluder& a, const FieldOccluder& b) {
    return a.field == b.field && a.occluderToWorld == b.occluderToWorld && a.instanceId == b.instanceId &&
           a.ownBox.min == b.ownBox.min && a.ownBox.max == b.ownBox.max;
  };
  if (replanned || !std::equal(now.begin(), now.end(), Occluders.begin(), Occluders.end(), same)) UseOccluders(now);
}

void FieldPass::UseFields(std::vector<std::shared_ptr<const BakedField>> fields) {
  FieldGpuData data = packFields(fields);
  Fields = std::move(fields);
  FieldData = std::move(data);
  Textures.fieldsChanged();
  try {
    OccluderData = packOccluders(Fields, Occluders, Settings.eval.bias);
  } catch (const std::invalid_argument&) {
    Occluders.clear();  // they named fields that are gone
    OccluderData = packOccluders(Fields, Occluders, Settings.eval.bias);
  }
  Textures.occludersChanged();
  Modified();
}

void FieldPass::UseOccluders(std::vector<FieldOccluder> occluders) {
  OccluderData = packOccluders(Fields, occluders, Settings.eval.bias);
  Occluders = std::move(occluders);
  Textures.occludersChanged();
  Modified();
}

void FieldPass::SetBakedAO(bool on) {
  if (on == BakedAO) return;
  BakedAO = on;
  Modified();
}

void FieldPass::Plan(const FrameContext& context, DeferredPlan& plan) {
  Constants = makeFieldConstants(Settings, context);
  DeferredConfig& c = plan.config;
  c.bakedAO = BakedAO;
  c.instanceIds = true;
  if (c.view == DebugView::Count) c.view = DebugView::AO;  // the counts, shown as the AO is
  const int grid = gridCode(FieldData);
  Cull.plan(plan, Constants.defines(0, 0));
  plan.stage(*StartStage, Constants.defines(0, 0));
  if (FieldData.hasCube) plan.stage(*CubeStage, Constants.defines(1, 0));
  if (grid) plan.stage(*GridStage, Constants.defines(0, grid));
  if (Constants.cones()) plan.stage(*ResolveStage, Constants.defines(0, 0));
  if (c.view == DebugView::Slice) {
    Slice.plan(plan, Constants.defines(FieldData.hasCube ? 1 : 0, grid));
    plan.overlay = true;
  }
}

vtkTextureObject* FieldPass::RenderAO(DeferredFrame& f) {
  std::string error;
  if (!Textures.upload(f.renWin, FieldData, OccluderData, Constants.cones(), error)) {
    vtkErrorMacro(<< error);
    return nullptr;
  }
  if (!RenderOccluders(f)) return nullptr;
  f.mark("fields");
  return f.aoTarget;
}

void FieldPass::RenderOverlay(DeferredFrame& f) {
  Slice.render(f, Textures, Constants, OccluderData.occluderCount, OccluderData.cubeCount, Settings.sliceAxis,
               Settings.slicePosition);
}

// The AO and z targets with the receivers' depth-stencil target, for the start and occluder draws.
bool FieldPass::AttachTargets(DeferredFrame& f) {
  const int w = f.targetWidth, h = f.targetHeight;
  if (Constants.cones()) {
    ensureTexture2D(StateTarget, f.renWin, TexFormat::RGBA32F, w, h);
    glBindImageTexture(0, StateTarget->GetHandle(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  } else {
    StateTarget = nullptr;
  }
  if (!DepthStencil || static_cast<int>(DepthStencil->GetWidth()) != w || static_cast<int>(DepthStencil->GetHeight()) != h) {
    DepthStencil = vtkSmartPointer<vtkTextureObject>::New();
    DepthStencil->SetContext(f.renWin);
    if (!DepthStencil->AllocateDepthStencil(w, h)) {
      vtkErrorMacro("could not allocate a depth-stencil target of " << w << "x" << h);
      return false;
    }
  }
  f.state->PushFramebufferBindings();
  f.fbo->Bind();
  f.fbo->AddColorAttachment(0, f.aoTarget);
  f.fbo->AddColorAttachment(1, f.zTarget);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D, DepthStencil->GetHandle(), 0);
  activateDrawBuffers(f.fbo, 2);
  f.fbo->Start(w, h);  // viewport; blend, depth and scissor tests off
  return true;
}

// Occlusion 0, view z, the receivers' depth and instance ids (and no cone yet).
void FieldPass::DrawStart(DeferredFrame& f, vtkShaderProgram* p) {
  vtkTextureObject* ids = f.gbuffer->GetInstanceIdTexture();
  ActiveTextures inputs{ids};
  f.bindCommon(p);
  p->SetUniformi("fieldIds", ids->GetTextureUnit());
  const int target[2] = {f.targetWidth, f.targetHeight};
  p->SetUniform2i("fieldTarget", target);
  if (Constants.cones()) p->SetUniformi("fieldState", 0);
  vtkOpenGLState* state = f.state;
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthFunc(GL_ALWAYS);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglEnable(GL_STENCIL_TEST);
  state->vtkglStencilFunc(GL_ALWAYS, 0, 0xFF);
  state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
  state->vtkglStencilMask(0xFF);
  StartStage->render();
  if (Constants.cones()) glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

// One draw per occluder of one kind whose sphere reaches the screen, scissored to the tile runs
// its receivers lie in, at the depth of the sphere's far side (the depth test GREATER), the
// stencil rejecting the occluder's own instance.
bool FieldPass::DrawOccluders(DeferredFrame& f, const TileDepths& tiles, bool cubes) {
  const int first = cubes ? 0 : OccluderData.cubeCount;
  const int end = cubes ? OccluderData.cubeCount : OccluderData.occluderCount;
  if (first == end) return true;
  FullScreenStage& stage = cubes ? *CubeStage : *GridStage;
  vtkShaderProgram* p = stage.use(f.renWin);
  if (!p) return false;
  vtkTextureObject* ids = f.gbuffer->GetInstanceIdTexture();
  std::vector<vtkTextureObject*> textures = Textures.textures(Constants.cones());
  textures.push_back(ids);
  ActiveTextures inputs(textures);
  f.bindCommon(p);
  Textures.bind(p, Constants);
  p->SetUniformi("fieldIds", ids->GetTextureUnit());
  const int target[2] = {f.targetWidth, f.targetHeight};
  p->SetUniform2i("fieldTarget", target);
  if (Constants.cones()) p->SetUniformi("fieldState", 0);
  const TargetGeometry geometry = targetGeometry(f);
  glm::dmat4 worldToView;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) worldToView[j][i] = f.worldToView[i * 4 + j];
  for (int k = first; k < end; ++k) {
    const OccluderRecord o = occluderRecord(OccluderData, k);
    const glm::dvec3 centre = glm::dvec3(worldToView * glm::dvec4(o.sphere[0], o.sphere[1], o.sphere[2], 1.0));
    const std::vector<TexelRect> runs = sphereTexelRuns(centre, o.sphere[3], geometry, tiles);
    if (runs.empty()) continue;
    const FieldRecord field = fieldRecord(FieldData, o.field);
    p->SetUniform4f("fieldM0", o.worldToField);
    p->SetUniform4f("fieldM1", o.worldToField + 4);
    p->SetUniform4f("fieldM2", o.worldToField + 8);
    p->SetUniform4f("fieldSphere", o.sphere);
    p->SetUniform1iv("fieldInfo", 4, field.info);
    p->SetUniform4f("fieldF0", field.floats);
    p->SetUniform4f("fieldF1", field.floats + 4);
    p->SetUniform4f("fieldF2", field.floats + 8);
    p->SetUniformi("fieldOwner", static_cast<int>(o.instanceId));
    p->SetUniform3f("fieldOwnMin", o.ownBox);
    p->SetUniform3f("fieldOwnMax", o.ownBox + 3);
    // The quad lies at the far side of the sphere (a little beyond, against rounding).
    const double far = windowDepth(f.depthToZ, centre.z - o.sphere[3] * 1.001 - 1e-6 * std::abs(centre.z));
    glDepthRange(far, far);
    // Receivers hold min(id, 255) >= 1: an owner the stencil cannot name, or one whose own pixels
    // are only those in its box, compares against 0, which passes them all (one test function for
    // every draw: one llvmpipe shader variant).
    const std::uint32_t owner = o.instanceId;
    const bool stencilNames = owner >= 1 && owner <= 254 && !o.sharedId;
    f.state->vtkglStencilFunc(GL_NOTEQUAL, stencilNames ? static_cast<int>(owner) : 0, 0xFF);
    for (const TexelRect& rect : runs) {
      f.state->vtkglScissor(rect.x0, rect.y0, rect.x1 - rect.x0 + 1, rect.y1 - rect.y0 + 1);
      stage.render();
      DrawnTexels += rect.area();
      ++DrawCalls;
    }
    if (Constants.cones()) glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);  // the next occluder reads these cones
    ++DrawnOccluders;
  }
  return true;
}

// Cones: their occlusion into the AO target.
bool FieldPass::ResolveCones(DeferredFrame& f) {
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  vtkShaderProgram* p = ResolveStage->use(f.renWin);
  if (!p) return false;
  ActiveTextures inputs{StateTarget};
  f.bindCommon(p);
  const int target[2] = {f.targetWidth, f.targetHeight};
  p->SetUniform2i("fieldTarget", target);
  p->SetUniformi("fieldStateTex", StateTarget->GetTextureUnit());
  ResolveStage->renderInto(f.fbo, {f.aoTarget});
  return true;
}

bool FieldPass::RenderOccluders(DeferredFrame& f) {
  TileDepths tiles;
  if (!Cull.readTileDepths(f, tiles)) return false;
  f.mark("cull");
  vtkShaderProgram* start = StartStage->use(f.renWin);
  if (!start) return false;
  vtkOpenGLState* state = f.state;
  vtkOpenGLState::ScopedglBlendFuncSeparate blendFunc(state);
  vtkOpenGLState::ScopedglEnableDisable stencilTest(state, GL_STENCIL_TEST);
  GLfloat depthRange[2];
  glGetFloatv(GL_DEPTH_RANGE, depthRange);
  if (!AttachTargets(f)) return false;
  DrawStart(f, start);

  activateDrawBuffers(f.fbo, 1);  // the z target keeps what the start wrote
  state->vtkglDepthFunc(GL_GREATER);  // the receiver is nearer than the sphere's far side
  state->vtkglDepthMask(GL_FALSE);
  state->vtkglStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  state->vtkglStencilMask(0);
  state->vtkglEnable(GL_SCISSOR_TEST);
  const int mode = Constants.mode;
  if (mode == 0) state->vtkglBlendFunc(GL_ONE_MINUS_DST_COLOR, GL_ONE);  // A + A_k - A A_k
  if (mode == 2) state->vtkglBlendFunc(GL_ONE, GL_ONE);                  // count
  if (mode != 1) state->vtkglEnable(GL_BLEND);
  DrawnOccluders = DrawCalls = 0;
  DrawnTexels = 0;
  const bool drawn = DrawOccluders(f, tiles, true) && DrawOccluders(f, tiles, false);

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
  return drawn && (!Constants.cones() || ResolveCones(f));
}

std::size_t FieldPass::FamilyMemoryBytes() const {
  return Textures.memoryBytes() + textureBytes(StateTarget) + textureBytes(DepthStencil) + Cull.memoryBytes();
}

void FieldPass::ReleaseFamily(vtkWindow* w) {
  Cull.release(w);
  StartStage->release(w);
  CubeStage->release(w);
  GridStage->release(w);
  ResolveStage->release(w);
  Slice.release(w);
  Textures.release();
  StateTarget = DepthStencil = nullptr;
}

}  // namespace aokit
