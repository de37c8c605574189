#include "voxel/StaticBake.h"

#include <memory>
#include <stdexcept>
#include <string>

#include "core/Geometry.h"
#include "core/Group.h"
#include "core/NodeVisitor.h"
#include "core/Transform.h"
#include "reference/EmbreeScene.h"
#include "voxel/VertexAOBake.h"

namespace aokit {

namespace {

bool isStaticWith(const GeometryInstance& inst, std::uint32_t bits) {
  return (inst.mask & kDynamic) == 0 && (inst.mask & bits) == bits && inst.geometry->mesh() &&
         !inst.geometry->mesh()->empty();
}

}  // namespace

StaticBake bakeStaticInstances(Node& root, const StaticBakeOptions& o) {
  if (o.rays < 1 || o.rays > 4096)
    throw std::invalid_argument("static bake: rays must be in 1..4096, got " + std::to_string(o.rays));
  const std::vector<GeometryInstance> all = collectInstances(root);
  // The static casters as a scene of their own (EmbreeScene takes a graph): the same meshes, placed
  // where they stand.
  auto statics = std::make_shared<Group>();
  StaticBake bake;
  for (const GeometryInstance& inst : all) {
    if (!isStaticWith(inst, kCastsAO)) continue;
    auto t = std::make_shared<Transform>();
    t->setMatrix(inst.world);
    t->addChild(std::make_shared<Geometry>(inst.geometry->mesh(), inst.geometry->albedo()));
    statics->addChild(t);
    ++bake.occluders;
  }
  std::vector<const GeometryInstance*> receivers;
  std::size_t total = 0;
  for (const GeometryInstance& inst : all)
    if (isStaticWith(inst, kVisible | kReceivesAO) && !bake.perInstance.count(inst.id)) {
      receivers.push_back(&inst);
      bake.perInstance[inst.id];  // claims the id: an instance is baked once
      total += inst.geometry->mesh()->positions.size();
    }
  const auto progress = [&](double f) {
    if (o.progress) o.progress(f);
  };
  progress(0.0);
  std::unique_ptr<EmbreeScene> embree;
  if (bake.occluders > 0) embree = std::make_unique<EmbreeScene>(*statics, kCastsAO);
  std::size_t done = 0;
  for (const GeometryInstance* inst : receivers) {
    const TriangleMesh& mesh = *inst->geometry->mesh();
    std::vector<float>& values = bake.perInstance[inst->id];
    if (!embree) {  // nothing static casts: nothing to bake
      values.assign(mesh.positions.size(), 0.0f);
    } else {
      VertexBakeOptions v;
      v.samples = o.rays;
      v.radius = o.radius;
      v.falloff = o.falloff;
      v.seed = o.seed;
      v.threads = o.threads;
      v.mode = VertexBakeMode::SurfaceFit;  // contact lines and buried vertices (VertexAOBake.h)
      const double from = total ? double(done) / total : 0.0, span = total ? double(mesh.positions.size()) / total : 0.0;
      v.progress = [&](double f) { progress(from + span * f); };
      values = bakeVertexAO(*embree, mesh, inst->world, v);
    }
    done += mesh.positions.size();
    bake.vertices += values.size();
  }
  progress(1.0);
  return bake;
}

}  // namespace aokit
