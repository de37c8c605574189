#include "scenes/SceneBuilding.h"

#include <glm/gtc/matrix_transform.hpp>

namespace aokit {

TransformPtr addPlaced(Group& parent, std::shared_ptr<const TriangleMesh> mesh, const glm::dmat4& matrix,
                       const glm::vec3& albedo, const std::string& name) {
  auto t = std::make_shared<Transform>();
  t->setMatrix(matrix);
  t->setName(name);
  auto g = std::make_shared<Geometry>(std::move(mesh), albedo);
  g->setName(name);
  t->addChild(g);
  parent.addChild(t);
  return t;
}

glm::dmat4 translation(const glm::dvec3& t) { return glm::translate(glm::dmat4(1.0), t); }

glm::dmat4 rotation(double degrees, const glm::dvec3& axis) {
  return glm::rotate(glm::dmat4(1.0), glm::radians(degrees), glm::normalize(axis));
}

glm::dmat4 scaling(const glm::dvec3& s) { return glm::scale(glm::dmat4(1.0), s); }

}  // namespace aokit
