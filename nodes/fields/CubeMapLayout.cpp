#include "fields/CubeMapLayout.h"

#include <cmath>

namespace aokit {

glm::dvec3 faceDirection(int face, double u, double v) {
  switch (face) {
    case 0: return {1.0, -v, -u};
    case 1: return {-1.0, -v, u};
    case 2: return {u, 1.0, v};
    case 3: return {u, -1.0, -v};
    case 4: return {u, -v, 1.0};
    default: return {-u, -v, -1.0};
  }
}

FaceCoordinates directionToFace(const glm::dvec3& d) {
  const double ax = std::abs(d.x), ay = std::abs(d.y), az = std::abs(d.z);
  FaceCoordinates f;
  if (ax >= ay && ax >= az && ax > 0.0) {
    f.face = d.x > 0.0 ? 0 : 1;
    f.u = (d.x > 0.0 ? -d.z : d.z) / ax;
    f.v = -d.y / ax;
  } else if (ay >= az && ay > 0.0) {
    f.face = d.y > 0.0 ? 2 : 3;
    f.u = d.x / ay;
    f.v = (d.y > 0.0 ? d.z : -d.z) / ay;
  } else if (az > 0.0) {
    f.face = d.z > 0.0 ? 4 : 5;
    f.u = (d.z > 0.0 ? d.x : -d.x) / az;
    f.v = -d.y / az;
  } else {
    f.face = 4;
  }
  return f;
}

}  // namespace aokit
