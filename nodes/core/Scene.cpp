#include "core/Scene.h"

#include "core/Geometry.h"
#include "core/NodeVisitor.h"

namespace aokit {

Bounds worldBounds(Node& root) {
  Bounds b;
  for (const auto& inst : collectInstances(root, kVisible | kCastsAO | kReceivesAO))
    if (inst.geometry->mesh()) b.extend(inst.geometry->mesh()->bounds().transformed(inst.world));
  return b;
}

}  // namespace aokit
