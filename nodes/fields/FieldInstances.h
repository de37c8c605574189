#pragma once
// Which field each casting instance of a scene uses (pure CPU, no baking here).
//
// A field is baked in its mesh's own units for R in those units. An instance placed by a
// similarity (rotation, uniform scale s, translation: L^T L = s^2 I for the linear part L of its
// world matrix) uses the field of its mesh baked for R / s, shared by every instance of that mesh
// at that scale, and its world matrix is the occluder transform O as is. Any other linear part
// (non-uniform scale, shear) cannot be undone by a similarity, so the instance gets a field of its
// own mesh with L applied (baked for R), and O = world L^-1: rigid at planning time, and it stays
// a similarity as long as later motion is (a Transform rotated or moved, not rescaled).
// A Geometry with a field file (FieldAttachment.h) uses the file's field for its similarity
// instances; its non-uniformly scaled instances are an error.
//
// Kind: fixed, or auto: a grid6 field for flat occluders (floors, walls, plates), a cube field for
// the rest. A radial field stores, along each direction from the occluder's centre, a function of
// the distance only; next to a large flat occluder the occlusion depends on the height above it,
// which along directions grazing the plane barely changes with the distance (1 / (a r^2 + b r + c)
// cannot follow it, and the receivers that matter, beside the plane, lie along exactly those
// directions). A grid stores it wherever it is. Flat: the smallest extent of the mesh along its
// principal axes is under a tenth of the middle one (a rod or a box is not flat, a plane is).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/NodeVisitor.h"
#include "core/TriangleMesh.h"
#include "fields/FieldBakeSettings.h"

namespace aokit {

struct PlannedField {
  FieldKind kind = FieldKind::Cube;
  std::shared_ptr<const TriangleMesh> mesh;  // the mesh to bake (the instance's own, or with L applied)
  double radius = 0.0;                       // R in that mesh's units
  std::string file;                          // a field file to load instead of baking, or empty
  std::string name;                          // for messages: the Geometry's name or "mesh <n>"
};

struct PlannedOccluder {
  int field = 0;
  std::uint32_t instanceId = 0;
  glm::dmat4 correction{1.0};  // O = world * correction (L^-1 for a field with L applied)
};

struct FieldPlan {
  std::vector<PlannedField> fields;
  std::vector<PlannedOccluder> occluders;  // in instance order
};

// True when the 3x3 part of m is a similarity (rotation or reflection times a uniform scale > 0);
// `scale` gets s.
bool isSimilarity(const glm::dmat4& m, double* scale = nullptr);

// Extents of the vertices along their principal axes, smallest first.
glm::dvec3 principalExtents(const TriangleMesh& mesh);
bool isFlat(const TriangleMesh& mesh);

// Plans the fields of casting instances (empty meshes are skipped). radius: the scene's R (world);
// kind: every field's, or empty for auto (above). The kind of a field file is the file's.
// Throws std::invalid_argument on a degenerate transform (zero scale, non-finite) or a field file
// on a non-uniformly scaled instance.
FieldPlan planFields(const std::vector<GeometryInstance>& instances, double radius,
                     std::optional<FieldKind> kind = std::nullopt);

}  // namespace aokit
