#include "fields/FieldTechnique.h"

#include <cmath>
#include <stdexcept>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkRenderer.h>

#include "core/AOScene.h"
#include "core/Geometry.h"
#include "core/Scene.h"
#include "fields/ContentHash.h"
#include "fields/FieldBaker.h"
#include "fields/FieldCache.h"
#include "fields/FieldFile.h"
#include "fields/HorizonLimit.h"
#include "render/ActorKeys.h"
#include "render/BakedAO.h"

namespace aokit {

void validate(const FieldTechniqueSettings& s) {
  validate(s.field);
  validate(s.pass);
}

namespace {
FieldPassSettings passSettings(const FieldTechniqueSettings& s) {
  FieldPassSettings p = s.pass;
  const FieldPassSettings constants = passSettingsFrom(s.field);
  p.combine = constants.combine;
  p.insideExponent = constants.insideExponent;
  p.insideOcclusion = constants.insideOcclusion;
  p.bias = constants.bias;
  p.gridWeights = constants.gridWeights;
  return p;
}

bool casts(const GeometryInstance& i) { return i.geometry && i.geometry->mesh() && !i.geometry->mesh()->empty(); }
}  // namespace

FieldTechnique::FieldTechnique(FieldTechniqueSettings s) : settings_(std::move(s)) { validate(settings_); }

std::size_t FieldTechnique::fieldBytes() const {
  std::size_t bytes = 0;
  for (const auto& f : fields_) bytes += f->radial.memoryBytes() + f->grid.memoryBytes();
  return bytes;
}

void FieldTechnique::prepare(AOScene& scene, const std::function<void(double)>& progress) {
  radius_ = settings_.field.radius > 0.0 ? settings_.field.radius : scene.aoRadius();
  falloff_ = settings_.field.falloff ? *settings_.field.falloff : scene.falloff();
  plan(scene, collectInstances(scene, kCastsAO), progress);
  revision_ = sceneRevision(scene);
}

std::shared_ptr<const BakedField> FieldTechnique::obtain(const PlannedField& f,
                                                         const std::function<void(double)>& progress) {
  const auto key = std::make_tuple(f.mesh.get(), f.radius, f.file);
  if (auto it = baked_.find(key); it != baked_.end()) return it->second.second;
  FieldSettings bakeSettings = settings_.field;
  bakeSettings.kind = f.kind;
  bakeSettings.combine = FieldCombine::Multiply;  // a run-time constant, not baked (grids take no cones)
  std::shared_ptr<BakedField> field;
  if (!f.file.empty()) {
    field = std::make_shared<BakedField>(readFieldFile(f.file));
    checkFieldMatches(field->info, meshContentHash(*f.mesh), f.radius, falloff_, f.file);
    ++report_.fromFile;
  } else if (settings_.cache) {
    CachedField c = FieldCache(settings_.cacheDirectory).getOrBake(*f.mesh, bakeSettings, f.radius, falloff_, progress);
    if (!c.warning.empty()) report_.warnings.push_back(c.warning);
    if (c.hit) {
      ++report_.fromCache;
    } else {
      ++report_.baked;
      report_.bakeSeconds += c.field.info.bakeSeconds;
    }
    field = std::make_shared<BakedField>(std::move(c.field));
  } else {
    field = std::make_shared<BakedField>(bakeField(*f.mesh, bakeSettings, f.radius, falloff_, progress));
    ++report_.baked;
    report_.bakeSeconds += field->info.bakeSeconds;
  }
  if (field->info.kind == FieldKind::Cube) updateHullBox(field->radial, *f.mesh);
  baked_[key] = {f.mesh, field};
  return field;
}

void FieldTechnique::plan(AOScene&, const std::vector<GeometryInstance>& instances,
                          const std::function<void(double)>& progress) {
  plan_ = planFields(instances, radius_, settings_.autoKind ? std::nullopt : std::optional<FieldKind>(settings_.field.kind));
  report_ = {};
  report_.fields = static_cast<int>(plan_.fields.size());
  report_.occluders = static_cast<int>(plan_.occluders.size());
  fields_.clear();
  const double count = static_cast<double>(plan_.fields.size());
  for (std::size_t i = 0; i < plan_.fields.size(); ++i) {
    auto part = [&progress, i, count](double f) {
      if (progress) progress((static_cast<double>(i) + f) / count);
    };
    fields_.push_back(obtain(plan_.fields[i], part));
  }
  if (progress) progress(1.0);
  // Which planned occluder each instance is (planFields keeps instance order, skipping empty meshes).
  plannedMesh_.clear();
  plannedScale_.clear();
  byInstance_.clear();
  std::size_t k = 0;
  for (const GeometryInstance& inst : instances) {
    if (!casts(inst)) continue;
    double s = 1.0;
    isSimilarity(inst.world * plan_.occluders[k].correction, &s);
    plannedMesh_.push_back(inst.geometry->mesh().get());
    plannedScale_.push_back(s);
    byInstance_[inst.id] = k++;
  }
  if (!place(instances)) throw std::logic_error("field: planned occluders do not place");
  if (pass_) {
    pass_->SetFields(fields_);
    pass_->SetOccluders(occluders_);
  }
}

bool FieldTechnique::place(const std::vector<GeometryInstance>& instances) {
  std::vector<FieldOccluder> out;
  for (const GeometryInstance& inst : instances) {
    if (!casts(inst)) continue;
    const auto it = byInstance_.find(inst.id);
    if (it == byInstance_.end()) return false;
    const std::size_t k = it->second;
    if (inst.geometry->mesh().get() != plannedMesh_[k]) return false;
    const glm::dmat4 o = inst.world * plan_.occluders[k].correction;
    double s = 0.0;
    if (!isSimilarity(o, &s) || std::abs(s - plannedScale_[k]) > 1e-6 * plannedScale_[k]) return false;
    out.push_back({plan_.occluders[k].field, o, inst.id});
  }
  if (out.size() != plan_.occluders.size()) return false;
  occluders_ = std::move(out);
  return true;
}

void FieldTechnique::attach(vtkRenderer* renderer, AOScene& scene) {
  previous_ = renderer->GetPass();
  pass_ = vtkSmartPointer<FieldPass>::New();
  pass_->SetSettings(passSettings(settings_));
  pass_->SetStageTiming(timing_);
  pass_->SetFields(fields_);
  pass_->SetOccluders(occluders_);
  pass_->SetSceneRadius(radius_);
  update(renderer, scene);
  applySelfOcclusion(renderer);
  renderer->SetPass(pass_);
}

void FieldTechnique::applySelfOcclusion(vtkRenderer* renderer) {
  // Instance id -> its field's per-vertex self-occlusion.
  std::map<std::uint32_t, const std::vector<float>*> byId;
  for (const FieldOccluder& o : occluders_)
    if (!fields_[o.field]->vertexOcclusion.empty()) byId[o.instanceId] = &fields_[o.field]->vertexOcclusion;
  if (pass_) pass_->SetBakedAO(!byId.empty());
  if (byId.empty()) return;
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor()) {
    const auto it = byId.find(propInstanceId(a));
    if (it == byId.end() || hasBakedAO(a)) continue;
    setBakedAO(a, *it->second);
    selfShaded_.push_back(a);
  }
}

void FieldTechnique::clearSelfOcclusion() {
  for (auto& a : selfShaded_)
    if (a && hasBakedAO(a)) clearBakedAO(a);
  selfShaded_.clear();
}

void FieldTechnique::update(vtkRenderer* renderer, AOScene& scene) {
  if (!pass_) return;
  const double radius = settings_.field.radius > 0.0 ? settings_.field.radius : scene.aoRadius();
  const Falloff falloff = settings_.field.falloff ? *settings_.field.falloff : scene.falloff();
  const std::uint64_t revision = sceneRevision(scene);
  if (radius != radius_ || falloff != falloff_) {
    radius_ = radius;
    falloff_ = falloff;
    plan(scene, collectInstances(scene, kCastsAO), {});
    pass_->SetSceneRadius(radius_);
    clearSelfOcclusion();  // baked for the old R or falloff
    applySelfOcclusion(renderer);
  } else if (revision != revision_) {
    const auto instances = collectInstances(scene, kCastsAO);
    if (place(instances)) {
      pass_->SetOccluders(occluders_);
    } else {
      plan(scene, instances, {});
      clearSelfOcclusion();  // fields may have changed under old actors
    }
    applySelfOcclusion(renderer);  // new actors, or meshes replaced under old ones
  }
  revision_ = revision;
}

void FieldTechnique::detach(vtkRenderer* renderer) {
  clearSelfOcclusion();
  if (pass_ && renderer->GetRenderWindow()) pass_->ReleaseGraphicsResources(renderer->GetRenderWindow());
  renderer->SetPass(previous_);
  pass_ = nullptr;
  previous_ = nullptr;
}

std::size_t FieldTechnique::memoryBytes() const { return pass_ ? pass_->MemoryBytes() : fieldBytes(); }

bool FieldTechnique::readAO(vtkRenderer* renderer, std::vector<float>& ao) {
  auto* renWin = vtkOpenGLRenderWindow::SafeDownCast(renderer->GetRenderWindow());
  return pass_ && renWin && pass_->ReadAO(renWin, ao);
}

void FieldTechnique::setStageTiming(bool on) {
  timing_ = on;
  if (pass_) pass_->SetStageTiming(on);
}

StageTimes FieldTechnique::stageTimes() { return pass_ ? pass_->GetStageTimes() : StageTimes{}; }

}  // namespace aokit
