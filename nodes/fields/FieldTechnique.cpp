#include "fields/FieldTechnique.h"

#include <cmath>
#include <stdexcept>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkRenderer.h>

#include "core/AOScene.h"
#include "core/Geometry.h"
#include "core/Scene.h"
#include "fields/FieldBaker.h"
#include "fields/FieldCache.h"
#include "fields/FieldFile.h"
#include "fields/HorizonLimit.h"
#include "render/ActorKeys.h"
#include "render/BakedAO.h"
#include "render/FrameContext.h"

namespace aokit {

namespace {
bool casts(const GeometryInstance& i) { return i.geometry && i.geometry->mesh() && !i.geometry->mesh()->empty(); }
}  // namespace

FieldTechnique::FieldTechnique(FieldSettings s) : settings_(std::move(s)) { validate(settings_); }

FieldPass* FieldTechnique::pass() const { return FieldPass::SafeDownCast(installedPass()); }

std::size_t FieldTechnique::fieldBytes() const {
  std::size_t bytes = 0;
  for (const auto& f : fields_) bytes += f->radial.memoryBytes() + f->grid.memoryBytes();
  return bytes;
}

void FieldTechnique::prepare(AOScene& scene, const std::function<void(double)>& progress) {
  const FrameContext context = frameContext(settings_.common, scene.aoRadius(), scene.falloff());
  radius_ = context.radius;
  falloff_ = context.falloff;
  plan(collectInstances(scene, kCastsAO), progress);
  revision_ = sceneRevision(scene);
}

std::shared_ptr<const BakedField> FieldTechnique::obtain(const PlannedField& f,
                                                         const std::function<void(double)>& progress) {
  const auto key = std::make_tuple(f.mesh.get(), f.radius, f.file);
  if (auto it = baked_.find(key); it != baked_.end()) return it->second.second;
  FieldBakeSettings bakeSettings = settings_.bake;
  bakeSettings.kind = f.kind;
  const BakeMesh mesh(*f.mesh);  // validated and hashed once, one Embree scene for all its bakes
  std::shared_ptr<BakedField> field;
  if (!f.file.empty()) {
    field = std::make_shared<BakedField>(readFieldFile(f.file));
    checkFieldMatches(field->info, mesh.hash(), f.radius, falloff_, f.file);
    ++report_.fromFile;
  } else if (settings_.cache) {
    CachedField c = FieldCache(settings_.cacheDirectory).getOrBake(mesh, bakeSettings, f.radius, falloff_, progress);
    if (!c.warning.empty()) report_.warnings.push_back(c.warning);
    if (c.hit) {
      ++report_.fromCache;
    } else {
      ++report_.baked;
      report_.bakeSeconds += c.field.info.bakeSeconds;
    }
    field = std::make_shared<BakedField>(std::move(c.field));
  } else {
    field = std::make_shared<BakedField>(bakeField(mesh, bakeSettings, f.radius, falloff_, progress));
    ++report_.baked;
    report_.bakeSeconds += field->info.bakeSeconds;
  }
  if (field->info.kind == FieldKind::Cube) updateHullBox(field->radial, *f.mesh);
  baked_[key] = {f.mesh, field};
  return field;
}

void FieldTechnique::plan(const std::vector<GeometryInstance>& instances, const std::function<void(double)>& progress) {
  plan_ = planFields(instances, radius_, settings_.kind);
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
  if (FieldPass* p = pass()) {
    p->SetFields(fields_);
    p->SetOccluders(occluders_);
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

vtkSmartPointer<vtkRenderPass> FieldTechnique::makePass() {
  auto p = vtkSmartPointer<FieldPass>::New();
  p->SetSettings(settings_);
  p->SetFields(fields_);
  p->SetOccluders(occluders_);
  return p;
}

void FieldTechnique::onAttach(vtkRenderer* renderer, AOScene&) { applySelfOcclusion(renderer); }

void FieldTechnique::applySelfOcclusion(vtkRenderer* renderer) {
  // Instance id -> its field's per-vertex self-occlusion.
  std::map<std::uint32_t, const std::vector<float>*> byId;
  for (const FieldOccluder& o : occluders_)
    if (!fields_[o.field]->vertexOcclusion.empty()) byId[o.instanceId] = &fields_[o.field]->vertexOcclusion;
  if (FieldPass* p = pass()) p->SetBakedAO(!byId.empty());
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

void FieldTechnique::onUpdate(vtkRenderer* renderer, AOScene& scene) {
  const FrameContext context = frameContext(settings_.common, scene.aoRadius(), scene.falloff());
  const std::uint64_t revision = sceneRevision(scene);
  if (context.radius != radius_ || context.falloff != falloff_) {
    radius_ = context.radius;
    falloff_ = context.falloff;
    plan(collectInstances(scene, kCastsAO), {});
    clearSelfOcclusion();  // baked for the old R or falloff
    applySelfOcclusion(renderer);
  } else if (revision != revision_) {
    const auto instances = collectInstances(scene, kCastsAO);
    if (place(instances)) {
      pass()->SetOccluders(occluders_);
    } else {
      plan(instances, {});
      clearSelfOcclusion();  // fields may have changed under old actors
    }
    applySelfOcclusion(renderer);  // new actors, or meshes replaced under old ones
  }
  revision_ = revision;
}

void FieldTechnique::onDetach(vtkRenderer*) { clearSelfOcclusion(); }

}  // namespace aokit
