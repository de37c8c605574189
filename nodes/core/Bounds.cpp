#include "core/Bounds.h"

namespace aokit {

Bounds Bounds::transformed(const glm::dmat4& m) const {
  Bounds out;
  if (!valid()) return out;
  for (int i = 0; i < 8; ++i) {
    glm::dvec3 c((i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z);
    out.extend(glm::dvec3(m * glm::dvec4(c, 1.0)));
  }
  return out;
}

}  // namespace aokit
