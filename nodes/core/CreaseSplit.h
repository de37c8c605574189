#pragma once
// A mesh's vertices split where its faces meet at a crease, for what is stored per point but must
// follow the facets: the self-occlusion bake (fields/SelfOcclusionBake.h). A tube with ten sides
// shares each ring vertex between two sides 36 degrees apart; its one vertex normal leans 18 degrees
// off both, so a value baked around it misses what each facet's hemisphere sees. Split as
// withFeatureNormals splits (FeatureNormals.h): around a vertex, faces meeting at more than the
// feature angle get a copy of it each, with their group's facet normal. The drawn mesh keeps its own
// normals: only the baked value is per copy.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "core/FeatureNormals.h"
#include "core/TriangleMesh.h"

namespace aokit {

// A point the bake added inside a mesh triangle (core/BakeRefinement.h): the midpoint of points a
// and b, as weights over up to three mesh vertices (unused ones weigh 0).
struct SplitMidpoint {
  std::uint32_t a = 0, b = 0;
  glm::uvec3 vertices{0};
  glm::vec3 weights{0.0f};
};

struct CreaseSplit {
  std::uint32_t vertexCount = 0;        // the mesh's; points 0..vertexCount-1 are its vertices
  std::vector<std::uint32_t> origin;    // per copy (point vertexCount + k): the vertex it copies
  std::vector<SplitMidpoint> midpoints; // after the copies: points a refinement added (empty without)
  std::vector<glm::uvec3> triangles;    // the mesh's triangles on the split points (empty without copies
                                        // or midpoints)
  std::vector<std::uint32_t> parent;    // per triangle: the mesh triangle it lies in (empty: the same
                                        // index; a refinement keeps them in the mesh's order)
  std::vector<glm::vec3> normals;       // per point: the hemisphere to bake around (a split vertex's
                                        // group's facet normal; elsewhere the mesh's own normal)

  std::size_t pointCount() const { return vertexCount + origin.size() + midpoints.size(); }
  bool splits() const { return !origin.empty() || !midpoints.empty(); }
  // Where point p lies on `mesh` (the mesh split).
  glm::vec3 position(const TriangleMesh& mesh, std::size_t p) const;
};

// The split of `mesh` (normals computed first when it has none). Meshes without creases above the
// angle (smooth scans, meshes whose creases already carry split vertices) get no copies and their
// own normals, so what is baked on them does not change.
CreaseSplit splitAtCreases(const TriangleMesh& mesh, double featureAngleDegrees = kDefaultFeatureAngle);

}  // namespace aokit
