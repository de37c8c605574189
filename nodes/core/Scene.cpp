#include "core/Scene.h"

#include <algorithm>

#include "core/Transform.h"

#include "core/Geometry.h"
#include "core/NodeVisitor.h"

namespace aokit {

Bounds worldBounds(Node& root) {
  Bounds b;
  for (const auto& inst : collectInstances(root, kVisible | kCastsAO | kReceivesAO))
    if (inst.geometry->mesh()) b.extend(inst.geometry->mesh()->bounds().transformed(inst.world));
  return b;
}

namespace {
class RevisionVisitor : public NodeVisitor {
 public:
  std::uint64_t latest = 0;
  void apply(Node& n) override { latest = std::max(latest, n.revision()); }
  void apply(Group& g) override {
    latest = std::max(latest, g.revision());
    g.traverse(*this);
  }
  void apply(Transform& t) override { apply(static_cast<Group&>(t)); }
  void apply(Geometry& g) override { apply(static_cast<Node&>(g)); }
  void apply(AOScene& s) override { apply(static_cast<Group&>(s)); }
};
}  // namespace

std::uint64_t sceneRevision(Node& root) {
  RevisionVisitor v;
  root.accept(v);
  return v.latest;
}

}  // namespace aokit
