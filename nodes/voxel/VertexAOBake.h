#pragma once
// Baked AO per vertex for static geometry (issue 9 item 5): the Embree reference's estimator, so
// that a static mesh can carry its AO as a vertex attribute (render/BakedAO.h) and the voxelizer
// cover only what moves (StaticDynamic.h, StaticBake.h). Two ways to choose the values:
//   AtVertices   the estimate at each vertex along its normal. Exact where the vertices are, but a
//                vertex on a contact line (a floor vertex at the foot of a wall) starts its rays on
//                the other surface and reads it as all around it, and a vertex inside another
//                caster (a floor vertex under a wall) reads nearly 1: the interpolation smears
//                both over the visible triangles next to them.
//   SurfaceFit   the estimate at points spread over every triangle (at most `spacing` apart), the
//                vertex values fitted to them by least squares (VertexAOFit.h), so that the
//                interpolated AO matches the surface, not its corners; points inside another
//                caster (more than half of their rays leave it through back faces, by the outward
//                winding) are left out of the fit.
// nodes/fields has a per-vertex self-occlusion bake of one mesh by itself (bakeVertexOcclusion);
// this one takes any occluders, and is the one static geometry uses.
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

#include "core/AOScene.h"
#include "core/TriangleMesh.h"
#include "reference/EmbreeScene.h"

namespace aokit {

enum class VertexBakeMode { AtVertices, SurfaceFit };

struct VertexBakeOptions {
  int samples = 256;                  //!< rays per estimate (vertex or surface point), >= 1
  double radius = 1.0;                //!< AO radius R, world units, > 0
  Falloff falloff = Falloff::Binary;  //!< as the reference's
  std::uint64_t seed = 1;             //!< same seed, same result
  int threads = 0;                    //!< 0 = all cores
  VertexBakeMode mode = VertexBakeMode::AtVertices;
  double spacing = 0.0;               //!< SurfaceFit: most world units between surface points
                                      //!<   (up to 16 x 16 per triangle), 0 = R / 8
  std::function<void(double)> progress;  //!< fraction done; throw to cancel (Progress::reporter())
};

// AO in [0, 1] for each vertex of `mesh` placed by `world`, occluded by `occluders` (usually the
// static casters, the mesh itself included). Vertices without a usable normal (or, SurfaceFit, on
// no triangle) get 0. Uses the mesh's normals (computed when it has none). Throws
// std::invalid_argument on bad options or an invalid mesh.
std::vector<float> bakeVertexAO(const EmbreeScene& occluders, const TriangleMesh& mesh, const glm::dmat4& world,
                                const VertexBakeOptions& options);

// The baked value at barycentric (u, v) of triangle t (weights 1 - u - v, u, v on its corners).
float interpolateVertexAO(const TriangleMesh& mesh, const std::vector<float>& ao, std::size_t triangle, float u,
                          float v);

// SurfaceFit's test for one surface point: true when more than half of `rays` hemisphere rays
// around n hit a triangle from behind (by the occluders' outward, counter-clockwise winding).
bool insideOccluder(const EmbreeScene& occluders, const glm::vec3& p, const glm::vec3& n, int rays, std::uint64_t key);

}  // namespace aokit
