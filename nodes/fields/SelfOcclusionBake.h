#pragma once
// Per-vertex ambient occlusion of an occluder by itself, for the scene's R and falloff: the part
// of the picture a field cannot give (seed 000's figures show fields plus precomputed self-shadows).
// Computed by the reference's own estimator (reference/AOReference.h) from each vertex with its
// normal, so it is the same quantity the reference measures, restricted to this one mesh.
#include <functional>
#include <vector>

#include "core/AOScene.h"
#include "core/CreaseSplit.h"
#include "fields/BakeMesh.h"

namespace aokit {

// One value in [0, 1] per point of splitAtCreases(mesh) (core/CreaseSplit.h): the vertices in
// mesh.positions order around their normals, then the copies at creases around their facets' normal
// (a mesh without creases: one a vertex). Vertices without normals get them computed (area-
// weighted). backSide: around the reversed normals (the side an open mesh shows
// through its cuts). progress may throw to cancel.
std::vector<float> bakeVertexOcclusion(const BakeMesh& mesh, double radius, Falloff falloff, int rays,
                                       int threads = 0, std::uint64_t seed = 1,
                                       const std::function<void(double)>& progress = {}, bool backSide = false);

// The field's self-occlusion: the crease split baked (on one side, or both: every point's front
// value, then every point's back value), then refined where the values step by more than
// kSelfRefineStep (core/BakeRefinement.h; `refinements` rounds, edges down to R / kSelfRefineMinEdge)
// and the new points baked, so contacts finer than the vertex spacing are drawn where they are.
struct SelfOcclusion {
  CreaseSplit points;
  std::vector<float> values;  // sides x points.pointCount()
};
constexpr int kMaxSelfRefinements = 3;
constexpr float kSelfRefineStep = 0.03f;
constexpr double kSelfRefineMinEdge = 64.0;
SelfOcclusion bakeSelfOcclusion(const BakeMesh& mesh, double radius, Falloff falloff, int rays, int sides,
                                int refinements, int threads = 0, std::uint64_t seed = 1,
                                const std::function<void(double)>& progress = {});
// The points bakeSelfOcclusion baked on, rebuilt from its values (a field file stores the values
// only). Throws std::invalid_argument when the values do not fit the mesh's refinement.
CreaseSplit selfOcclusionPoints(const TriangleMesh& mesh, const std::vector<float>& values, int sides, double radius,
                                int refinements);

}  // namespace aokit
