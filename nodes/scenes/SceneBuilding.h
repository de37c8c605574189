#pragma once
// Small helpers shared by the built-in scene builders: place a mesh under a group, build matrices.
#include <memory>

#include <glm/glm.hpp>

#include "core/Geometry.h"
#include "core/Group.h"
#include "core/Transform.h"
#include "core/TriangleMesh.h"

namespace aokit {

// Adds Transform(matrix) -> Geometry(mesh, albedo) under `parent` and returns the transform, so
// that animated scenes can keep a handle on it.
TransformPtr addPlaced(Group& parent, std::shared_ptr<const TriangleMesh> mesh, const glm::dmat4& matrix,
                       const glm::vec3& albedo, const std::string& name = {});

glm::dmat4 translation(const glm::dvec3& t);
// Rotation by `degrees` about `axis` (need not be unit length; must not be zero).
glm::dmat4 rotation(double degrees, const glm::dvec3& axis);
glm::dmat4 scaling(const glm::dvec3& s);

}  // namespace aokit
