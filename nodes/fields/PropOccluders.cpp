#include "fields/PropOccluders.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include <vtkPolyData.h>
#include <vtkProp.h>
#include <vtkSetGet.h>

#include "render/ActorKeys.h"
#include "render/PolyDataMesh.h"

namespace aokit {

void PropOccluders::warnOnce(vtkProp* prop, const std::string& why) {
  for (const auto& p : warned_)
    if (p == prop) return;
  warned_.erase(std::remove_if(warned_.begin(), warned_.end(), [](const auto& p) { return p == nullptr; }), warned_.end());
  warned_.emplace_back(prop);
  vtkGenericWarningMacro("aokit field: a " << prop->GetClassName() << " (" << static_cast<void*>(prop)
                                           << ") casts no AO: " << why);
}

std::shared_ptr<Geometry> PropOccluders::geometryOf(const PropMesh& m) {
  sources_.erase(std::remove_if(sources_.begin(), sources_.end(), [](const Source& s) { return s.poly == nullptr; }),
                 sources_.end());
  auto it = std::find_if(sources_.begin(), sources_.end(), [&](const Source& s) { return s.poly == m.poly; });
  if (it != sources_.end() && it->mtime == m.poly->GetMTime()) return it->geometry;
  if (it == sources_.end()) it = sources_.insert(sources_.end(), Source{m.poly, 0, nullptr});
  it->mtime = m.poly->GetMTime();
  it->geometry = nullptr;
  auto mesh = std::make_shared<TriangleMesh>(triangleMeshOf(*m.poly));
  if (mesh->empty()) return nullptr;  // lines and points: no surface, nothing to say
  try {
    mesh->validate();
  } catch (const std::exception& e) {
    warnOnce(m.prop, e.what());
    return nullptr;
  }
  it->geometry = std::make_shared<Geometry>(mesh, glm::vec3(0.8f));
  return it->geometry;
}

std::vector<PropOccluders::Instance> PropOccluders::instances(vtkRenderer* renderer, RankExchange* ranks) {
  std::vector<Instance> out;
  for (const PropMesh& m : meshes_.collect(renderer, ranks)) {
    std::shared_ptr<Geometry> g = geometryOf(m);
    if (!g) continue;
    const double det = glm::determinant(glm::dmat3(m.modelToWorld));
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) {
      warnOnce(m.prop, "its matrix is degenerate (a zero or non-finite scale)");
      continue;
    }
    const Bounds box = g->mesh()->bounds().transformed(m.modelToWorld);
    out.push_back({{g.get(), m.modelToWorld, ~0u, ensurePropInstanceId(m.keys)}, box, g});
  }
  return out;
}

bool PropOccluders::place(const std::vector<Instance>& found) {
  if (found.size() != plannedGeometry_.size()) return false;
  std::map<std::uint32_t, int> perId;
  for (const Instance& i : found) ++perId[i.geometry.id];
  std::vector<FieldOccluder> out;
  for (std::size_t k = 0; k < found.size(); ++k) {
    const GeometryInstance& inst = found[k].geometry;
    if (inst.geometry != plannedGeometry_[k].get()) return false;
    const glm::dmat4 o = inst.world * plan_.occluders[k].correction;
    double s = 0.0;
    if (!isSimilarity(o, &s) || std::abs(s - plannedScale_[k]) > 1e-6 * plannedScale_[k]) return false;
    FieldOccluder occluder{plan_.occluders[k].field, o, inst.id, {}};
    if (perId[inst.id] > 1) {
      const glm::dvec3 grow(0.02 * radius_);
      occluder.ownBox = {found[k].box.min - grow, found[k].box.max + grow};
    }
    out.push_back(occluder);
  }
  occluders_ = std::move(out);
  return true;
}

bool PropOccluders::update(vtkRenderer* renderer, const FieldSettings& settings, double radius, Falloff falloff,
                           const std::function<void(double)>& progress, RankExchange* ranks) {
  const std::vector<Instance> found = instances(renderer, ranks);
  const bool sameContext = planned_ && radius == radius_ && falloff == falloff_ && settings.kind == kind_;
  if (sameContext && place(found)) return false;
  // The props' signature: which meshes, at which scales (a failed bake is not retried until it changes).
  std::ostringstream signature;
  signature << radius << ' ' << static_cast<int>(falloff);
  for (const Instance& i : found) {
    double s = 0.0;
    const bool similar = isSimilarity(i.geometry.world, &s);
    signature << ' ' << i.geometry.geometry << ':' << (similar ? s : -1.0);
  }
  if (signature.str() == failedBake_) return false;
  radius_ = radius;
  falloff_ = falloff;
  kind_ = settings.kind;
  planned_ = false;
  fields_.clear();
  occluders_.clear();
  plannedGeometry_.clear();
  plannedScale_.clear();
  std::vector<GeometryInstance> instances;
  for (const Instance& i : found) instances.push_back(i.geometry);
  FieldSettings bake = settings;
  bake.bake.selfOcclusion = false;
  try {
    plan_ = planFields(instances, radius_, kind_);
    fields_ = store_.obtain(plan_, bake, falloff_, report_, progress);
  } catch (const std::exception& e) {
    vtkGenericWarningMacro("aokit field: no fields for this renderer's props: " << e.what());
    failedBake_ = signature.str();
    fields_.clear();
    return true;
  }
  failedBake_.clear();
  for (std::size_t k = 0; k < instances.size(); ++k) {
    double s = 1.0;
    isSimilarity(instances[k].world * plan_.occluders[k].correction, &s);
    plannedGeometry_.push_back(found[k].held);
    plannedScale_.push_back(s);
  }
  planned_ = true;
  if (!place(found)) throw std::logic_error("field: planned occluders do not place");
  return true;
}

void PropOccluders::clear() {
  planned_ = false;
  failedBake_.clear();
  store_.clear();
}

}  // namespace aokit
