#pragma once
#include <memory>

#include <glm/glm.hpp>

#include "core/Node.h"
#include "core/TriangleMesh.h"

namespace aokit {

// A leaf: a shared, immutable mesh plus its material albedo (diffuse reflectance, 0..1 per channel).
class Geometry : public Node {
 public:
  Geometry() = default;
  Geometry(std::shared_ptr<const TriangleMesh> mesh, glm::vec3 albedo) : mesh_(std::move(mesh)), albedo_(albedo) {}
  void accept(NodeVisitor& visitor) override;

  const std::shared_ptr<const TriangleMesh>& mesh() const { return mesh_; }
  void setMesh(std::shared_ptr<const TriangleMesh> mesh) { mesh_ = std::move(mesh); touch(); ++meshRevision_; }
  // Changes only when the mesh itself is replaced: renderers rebuild buffers on this, not on revision().
  std::uint64_t meshRevision() const { return meshRevision_; }

  const glm::vec3& albedo() const { return albedo_; }
  void setAlbedo(const glm::vec3& a) { albedo_ = a; touch(); }

 private:
  std::shared_ptr<const TriangleMesh> mesh_;
  glm::vec3 albedo_{0.8f};
  std::uint64_t meshRevision_ = 0;
};

using GeometryPtr = std::shared_ptr<Geometry>;

}  // namespace aokit
