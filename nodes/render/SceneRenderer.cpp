#include "render/SceneRenderer.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "core/Geometry.h"
#include "core/NodeVisitor.h"
#include "render/ActorKeys.h"
#include "render/BakedAO.h"

namespace aokit {

struct SceneRenderer::ActorEntry {
  vtkSmartPointer<vtkActor> actor = vtkSmartPointer<vtkActor>::New();
  std::uint64_t geometryRevision = ~0ull;
  std::uint64_t meshRevision = ~0ull;
  glm::dmat4 world{0.0};
  std::uint32_t mask = ~0u, instanceId = 0;
  ShadingMode mode = ShadingMode::Lit;
  std::uint64_t seen = 0;
};

vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.positions.size()));
  for (std::size_t i = 0; i < mesh.positions.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), mesh.positions[i].x, mesh.positions[i].y, mesh.positions[i].z);
  vtkNew<vtkCellArray> cells;
  cells->AllocateExact(static_cast<vtkIdType>(mesh.triangles.size()), static_cast<vtkIdType>(mesh.triangles.size() * 3));
  for (const auto& t : mesh.triangles) {
    const vtkIdType ids[3] = {t.x, t.y, t.z};
    cells->InsertNextCell(3, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(cells);
  if (mesh.normals.size() == mesh.positions.size()) {
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh.normals.size()));
    for (std::size_t i = 0; i < mesh.normals.size(); ++i)
      normals->SetTypedTuple(static_cast<vtkIdType>(i), &mesh.normals[i].x);
    poly->GetPointData()->SetNormals(normals);
  }
  return poly;
}

SceneRenderer::SceneRenderer(vtkRenderer* renderer) : renderer_(renderer) {}

SceneRenderer::~SceneRenderer() {
  if (attached_) attached_->detach(renderer_);
  for (auto& kv : actors_) renderer_->RemoveActor(kv.second->actor);
}

void SceneRenderer::setScene(AOScenePtr root) {
  if (attached_) attached_->detach(renderer_);
  attached_.reset();
  for (auto& kv : actors_) renderer_->RemoveActor(kv.second->actor);
  actors_.clear();
  root_ = std::move(root);
}

void SceneRenderer::setShadingMode(ShadingMode mode) { mode_ = mode; }

vtkPolyData* SceneRenderer::polyDataFor(const std::shared_ptr<const TriangleMesh>& mesh) {
  auto it = polyCache_.find(mesh.get());
  if (it != polyCache_.end() && !it->second.first.expired()) return it->second.second;
  auto poly = toPolyData(*mesh);
  ++meshUploads_;
  polyCache_[mesh.get()] = {mesh, poly};
  return poly;
}

void SceneRenderer::applyMaterial(vtkActor* actor, const Geometry& g) const {
  vtkProperty* p = actor->GetProperty();
  p->SetSpecular(0.0);
  if (mode_ == ShadingMode::AOOnly) {
    p->SetColor(1.0, 1.0, 1.0);
    p->SetAmbient(1.0);
    p->SetDiffuse(0.0);
  } else {
    p->SetColor(g.albedo().r, g.albedo().g, g.albedo().b);
    p->SetAmbient(0.3);
    p->SetDiffuse(0.7);
  }
}

void SceneRenderer::sync() {
  if (!root_) return;
  ++syncCount_;
  const auto instances = collectInstances(*root_, kVisible);
  std::map<const Geometry*, int> occurrence;
  for (const auto& inst : instances) {
    const Geometry& g = *inst.geometry;
    if (!g.mesh() || g.mesh()->empty()) continue;
    const auto key = std::make_pair(&g, occurrence[&g]++);
    auto& slot = actors_[key];
    if (!slot) {
      slot = std::make_unique<ActorEntry>();
      vtkNew<vtkPolyDataMapper> mapper;
      slot->actor->SetMapper(mapper);
      renderer_->AddActor(slot->actor);
    }
    ActorEntry& e = *slot;
    e.seen = syncCount_;
    if (e.meshRevision != g.meshRevision()) {
      setActorInput(e.actor, polyDataFor(g.mesh()));  // keeps baked AO that still fits
      e.meshRevision = g.meshRevision();
    }
    if (e.geometryRevision != g.revision() || e.mode != mode_) {
      applyMaterial(e.actor, g);
      e.geometryRevision = g.revision();
      e.mode = mode_;
    }
    if (e.mask != inst.mask || e.instanceId != inst.id) {
      tagProp(e.actor, inst.mask, inst.id);
      e.mask = inst.mask;
      e.instanceId = inst.id;
    }
    if (e.world != inst.world) {
      vtkNew<vtkMatrix4x4> m;
      for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) m->SetElement(r, c, inst.world[c][r]);  // glm is column-major
      e.actor->SetUserMatrix(m);
      e.world = inst.world;
    }
  }
  for (auto it = actors_.begin(); it != actors_.end();) {
    if (it->second->seen != syncCount_) {
      renderer_->RemoveActor(it->second->actor);
      it = actors_.erase(it);
    } else {
      ++it;
    }
  }
  for (auto it = polyCache_.begin(); it != polyCache_.end();)
    it = it->second.first.expired() ? polyCache_.erase(it) : std::next(it);
  syncTechnique();
}

void SceneRenderer::syncTechnique() {
  const auto wanted = applyTechnique_ ? root_->technique() : nullptr;
  if (wanted != attached_) {
    if (attached_) attached_->detach(renderer_);
    attached_ = wanted;
    if (attached_) {
      attached_->ensurePrepared(*root_);
      attached_->attach(renderer_, *root_);
    }
  }
  if (attached_) attached_->update(renderer_, *root_);
}

void SceneRenderer::applyCamera(const Camera& c) {
  vtkCamera* cam = renderer_->GetActiveCamera();
  cam->SetPosition(c.position.x, c.position.y, c.position.z);
  cam->SetFocalPoint(c.focalPoint.x, c.focalPoint.y, c.focalPoint.z);
  cam->SetViewUp(c.viewUp.x, c.viewUp.y, c.viewUp.z);
  cam->SetViewAngle(c.viewAngleDeg);
  cam->OrthogonalizeViewUp();
  renderer_->ResetCameraClippingRange();
}

}  // namespace aokit
