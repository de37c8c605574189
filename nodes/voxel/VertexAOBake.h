#pragma once
// Baked AO per vertex for static geometry (issue 9 item 5): the Embree reference's estimator run
// from every vertex along its normal, so that a static mesh can carry its AO as a vertex
// attribute and the voxelizer cover only what moves. Small on purpose: nodes/fields may hold a
// richer per-vertex bake; the two can merge.
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "core/AOScene.h"
#include "core/TriangleMesh.h"
#include "reference/EmbreeScene.h"

namespace aokit {

struct VertexBakeOptions {
  int samples = 256;                  //!< rays per vertex, >= 1
  double radius = 1.0;                //!< AO radius R, world units, > 0
  Falloff falloff = Falloff::Binary;  //!< as the reference's
  std::uint64_t seed = 1;             //!< same seed, same result
  int threads = 0;                    //!< 0 = all cores
  std::function<void(double)> progress;  //!< fraction done; throw to cancel (Progress::reporter())
};

// AO in [0, 1] for each vertex of `mesh` placed by `world`, occluded by `occluders` (usually the
// static casters, the mesh itself included). Vertices without a usable normal get 0. Uses the
// mesh's normals (computed when it has none). Throws std::invalid_argument on bad options or an
// invalid mesh.
std::vector<float> bakeVertexAO(const EmbreeScene& occluders, const TriangleMesh& mesh, const glm::dmat4& world,
                                const VertexBakeOptions& options);

// The baked value at barycentric (u, v) of triangle t (weights 1 - u - v, u, v on its corners).
float interpolateVertexAO(const TriangleMesh& mesh, const std::vector<float>& ao, std::size_t triangle, float u,
                          float v);

}  // namespace aokit
