#include "fields/GridField.h"

namespace aokit {

glm::dmat4 GridField::fieldFromOccluder() const {
  glm::dmat4 f(1.0);
  for (int a = 0; a < 3; ++a) {
    f[a][a] = 1.0 / size[a];
    f[3][a] = -origin[a] / size[a];
  }
  return f;
}

}  // namespace aokit
