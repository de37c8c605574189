#pragma once
// Procedural meshes for built-in scenes and scene files. All are wound counter-clockwise seen from
// outside (right-hand rule gives the outward normal) and come with unit per-vertex normals.
#include <memory>

#include <glm/glm.hpp>

#include "core/TriangleMesh.h"

namespace aokit {

// Sphere centred at the origin; `slices` around z (>= 3), `stacks` pole to pole (>= 2).
// Smooth normals. Triangles: 2 * slices * (stacks - 1).
std::shared_ptr<TriangleMesh> makeUVSphere(double radius, int slices, int stacks);

// Axis-aligned box centred at the origin with edge lengths `size`. Flat normals: 24 vertices,
// four per face, so that edges stay sharp under smooth shading.
std::shared_ptr<TriangleMesh> makeBox(const glm::dvec3& size);

// Capped cylinder along +z with its base disc at z = 0 and its top at z = height (so it stands on
// the floor without a shift). Smooth side, flat caps. Triangles: 4 * segments.
std::shared_ptr<TriangleMesh> makeCylinder(double radius, double height, int segments);

// Rectangle in z = 0 centred at the origin, normal +z, split into nx * ny cells of two triangles.
std::shared_ptr<TriangleMesh> makeGridPlane(double sizeX, double sizeY, int nx, int ny);

}  // namespace aokit
