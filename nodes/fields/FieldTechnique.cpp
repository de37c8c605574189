#include "fields/FieldTechnique.h"

#include <cmath>
#include <stdexcept>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkRenderer.h>

#include "core/AOScene.h"
#include "core/CreaseSplit.h"
#include "fields/SelfOcclusionBake.h"
#include "core/Geometry.h"
#include "core/Scene.h"
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

void FieldTechnique::plan(const std::vector<GeometryInstance>& instances, const std::function<void(double)>& progress) {
  plan_ = planFields(instances, radius_, settings_.kind);
  fields_ = store_.obtain(plan_, settings_, falloff_, report_, progress);
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
    out.push_back({plan_.occluders[k].field, o, inst.id, {}});
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
  // Instance id -> its occluder, for those whose field carries per-point self-occlusion.
  std::map<std::uint32_t, const FieldOccluder*> byId;
  for (const FieldOccluder& o : occluders_)
    if (!fields_[o.field]->vertexOcclusion.empty()) byId[o.instanceId] = &o;
  if (FieldPass* p = pass()) p->SetBakedAO(!byId.empty());
  if (byId.empty()) return;
  // Per field: the points its values are on, as its bake or the cache left them, else rebuilt.
  std::map<std::size_t, std::shared_ptr<const CreaseSplit>> splits;
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* a = actors->GetNextActor()) {
    const auto it = byId.find(propInstanceId(a));
    if (it == byId.end() || hasBakedAO(a)) continue;
    const BakedField& field = *fields_[it->second->field];
    if (field.info.selfPointCount == field.info.vertexCount) {
      setBakedAO(a, field.vertexOcclusion);
    } else {
      std::shared_ptr<const CreaseSplit>& points = splits[it->second->field];
      if (!points) points = field.selfPoints;
      if (!points)
        points = std::make_shared<const CreaseSplit>(
            selfOcclusionPoints(*plannedMesh_[byInstance_.at(it->first)], field.vertexOcclusion,
                                field.info.selfOcclusionBack ? 2 : 1, field.info.radius, field.info.selfRefinements));
      setBakedAO(a, field.vertexOcclusion, *points);
    }
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
