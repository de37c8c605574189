#pragma once
#include <glm/glm.hpp>

#include "core/Group.h"

namespace aokit {

// Group whose children are placed by an affine matrix (column vectors, as glm).
class Transform : public Group {
 public:
  void accept(NodeVisitor& visitor) override;

  const glm::dmat4& matrix() const { return matrix_; }
  void setMatrix(const glm::dmat4& m) { matrix_ = m; touch(); }

 private:
  glm::dmat4 matrix_{1.0};
};

using TransformPtr = std::shared_ptr<Transform>;

}  // namespace aokit
