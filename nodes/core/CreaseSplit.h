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

struct CreaseSplit {
  std::uint32_t vertexCount = 0;        // the mesh's; points 0..vertexCount-1 are its vertices
  std::vector<std::uint32_t> origin;    // per copy (point vertexCount + k): the vertex it copies
  std::vector<glm::uvec3> triangles;    // the mesh's triangles on the split points (empty without copies)
  std::vector<glm::vec3> normals;       // per point: the hemisphere to bake around (a split vertex's
                                        // group's facet normal; elsewhere the mesh's own normal)

  std::size_t pointCount() const { return vertexCount + origin.size(); }
  bool splits() const { return !origin.empty(); }
};

// The split of `mesh` (normals computed first when it has none). Meshes without creases above the
// angle (smooth scans, meshes whose creases already carry split vertices) get no copies and their
// own normals, so what is baked on them does not change.
CreaseSplit splitAtCreases(const TriangleMesh& mesh, double featureAngleDegrees = kDefaultFeatureAngle);

}  // namespace aokit
