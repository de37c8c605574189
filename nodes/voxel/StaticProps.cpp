#include "voxel/StaticProps.h"

#include <map>
#include <memory>

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include "core/Geometry.h"
#include "core/NodeVisitor.h"
#include "core/Transform.h"
#include "render/ActorKeys.h"
#include "render/BakedAO.h"
#include "voxel/CasterBuffers.h"

namespace aokit {

namespace {

template <class F>
void forEachActor(vtkRenderer* renderer, F&& f) {
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* a = actors->GetNextActor(it)) f(a);
}

std::size_t pointCount(vtkActor* actor) {
  vtkPolyData* poly = CasterBuffers::propPolyData(actor);
  return poly ? static_cast<std::size_t>(poly->GetNumberOfPoints()) : 0;
}

// The polydata's triangles (polygons as fans, strips alternated) in model coordinates, its point
// normals when it has them: one mesh vertex per point, so baked values map back one to one.
std::shared_ptr<TriangleMesh> meshOf(vtkPolyData* poly) {
  auto m = std::make_shared<TriangleMesh>();
  const vtkIdType np = poly->GetNumberOfPoints();
  m->positions.resize(static_cast<std::size_t>(np));
  for (vtkIdType i = 0; i < np; ++i) {
    double p[3];
    poly->GetPoint(i, p);
    m->positions[static_cast<std::size_t>(i)] = glm::vec3(p[0], p[1], p[2]);
  }
  vtkIdType n;
  const vtkIdType* ids;
  vtkCellArray* polys = poly->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
    for (vtkIdType k = 1; k + 1 < n; ++k)
      m->triangles.emplace_back(static_cast<unsigned>(ids[0]), static_cast<unsigned>(ids[k]), static_cast<unsigned>(ids[k + 1]));
  vtkCellArray* strips = poly->GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(n, ids);)
    for (vtkIdType k = 0; k + 2 < n; ++k) {
      const bool odd = (k & 1) != 0;
      m->triangles.emplace_back(static_cast<unsigned>(ids[k + (odd ? 1 : 0)]), static_cast<unsigned>(ids[k + (odd ? 0 : 1)]),
                                static_cast<unsigned>(ids[k + 2]));
    }
  vtkDataArray* normals = poly->GetPointData()->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3 && normals->GetNumberOfTuples() == np) {
    m->normals.resize(m->positions.size());
    for (vtkIdType i = 0; i < np; ++i) {
      double v[3];
      normals->GetTuple(i, v);
      m->normals[static_cast<std::size_t>(i)] = glm::vec3(v[0], v[1], v[2]);
    }
  } else {
    m->computeNormals();
  }
  return m;
}

}  // namespace

std::size_t applyStaticBake(vtkRenderer* renderer, const StaticBake& bake) {
  std::size_t applied = 0;
  if (bake.perInstance.empty()) return 0;
  forEachActor(renderer, [&](vtkActor* a) {
    const auto it = bake.perInstance.find(propInstanceId(a));
    if (it == bake.perInstance.end() || hasBakedAO(a) || pointCount(a) != it->second.size()) return;
    setBakedAO(a, it->second);
    ++applied;
  });
  return applied;
}

void clearStaticBake(vtkRenderer* renderer, const StaticBake& bake) {
  if (bake.perInstance.empty()) return;
  forEachActor(renderer, [&](vtkActor* a) {
    if (bake.perInstance.count(propInstanceId(a)) && hasBakedAO(a)) clearBakedAO(a);
  });
}

std::size_t bakeStaticProps(vtkRenderer* renderer, const StaticBakeOptions& options) {
  // The static props as a scene graph of their own, one instance per actor.
  auto root = std::make_shared<Group>();
  std::map<const Geometry*, vtkActor*> actorOf;
  forEachActor(renderer, [&](vtkActor* a) {
    if (!a->GetVisibility() || propDynamic(a)) return;
    vtkPolyData* poly = CasterBuffers::propPolyData(a);
    if (!poly || poly->GetNumberOfPoints() == 0) return;
    auto mesh = meshOf(poly);
    if (mesh->empty()) return;
    auto t = std::make_shared<Transform>();
    t->setMatrix(CasterBuffers::propMatrix(a));
    auto g = std::make_shared<Geometry>(mesh, glm::vec3(0.8f));
    g->setMask(kVisible | (propCastsAO(a) ? kCastsAO : 0u) | (propReceivesAO(a) ? kReceivesAO : 0u));
    t->addChild(g);
    root->addChild(t);
    actorOf[g.get()] = a;
  });
  const StaticBake bake = bakeStaticInstances(*root, options);
  std::size_t applied = 0;
  for (const GeometryInstance& inst : collectInstances(*root)) {
    const auto values = bake.perInstance.find(inst.id);
    if (values == bake.perInstance.end()) continue;
    setBakedAO(actorOf.at(inst.geometry), values->second);
    ++applied;
  }
  return applied;
}

}  // namespace aokit
