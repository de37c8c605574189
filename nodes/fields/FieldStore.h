#pragma once
// The baked fields of a plan (FieldInstances.h), each obtained once: kept in memory by mesh, R,
// kind, falloff and file across re-plans; otherwise read from the field file the scene names,
// from the bake cache (FieldCache.h, keyed by content), or baked with Embree. Shared by the
// scene-graph technique (FieldTechnique.h) and the drop-in pass's own occluders (PropOccluders.h).
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "fields/BakedField.h"
#include "fields/FieldInstances.h"
#include "fields/FieldSettings.h"

namespace aokit {

// What obtaining a plan's fields did.
struct FieldPrepareReport {
  int fields = 0, occluders = 0;
  int baked = 0, fromCache = 0, fromFile = 0;
  double bakeSeconds = 0.0;  // summed over the fields baked now
  std::vector<std::string> warnings;
};

class FieldStore {
 public:
  // The plan's fields in its order; progress goes 0 -> 1 over them. Throws std::runtime_error on a
  // bad field file, an Embree error or a cancelled bake, std::invalid_argument on an invalid mesh.
  std::vector<std::shared_ptr<const BakedField>> obtain(const FieldPlan& plan, const FieldSettings& settings,
                                                        Falloff falloff, FieldPrepareReport& report,
                                                        const std::function<void(double)>& progress);
  // Forgets every kept field (new bake settings).
  void clear() { kept_.clear(); }
  std::size_t kept() const { return kept_.size(); }

 private:
  std::shared_ptr<const BakedField> one(const PlannedField& f, const FieldSettings& settings, Falloff falloff,
                                        FieldPrepareReport& report, const std::function<void(double)>& progress);

  using Key = std::tuple<const TriangleMesh*, double, FieldKind, Falloff, std::string>;
  // The mesh is held so that its address cannot be reused by another.
  std::map<Key, std::pair<std::shared_ptr<const TriangleMesh>, std::shared_ptr<const BakedField>>> kept_;
};

}  // namespace aokit
