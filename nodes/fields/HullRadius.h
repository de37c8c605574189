#pragma once
// r0(w) of seed 000: the distance from the field centre to the occluder's convex hull along w.
//
// The hull is kept as the intersection of its support half-spaces {x : u_k.x <= h(u_k)} over many
// directions u_k (a spherical Fibonacci set plus the 26 axis, edge and corner directions of a box,
// so that the boxes of built-in scenes are exact). Along w, r0(w) = min over u_k.w > 0 of
// h(u_k) / (u_k.w). With enough directions this is the convex hull up to a sliver: it is never
// smaller than the hull, and larger by at most the polytope's rounding (about (1 - cos(spacing))
// of the radius, 1e-3 with the default 4096 directions on smooth parts).
#include <vector>

#include <glm/glm.hpp>

#include "core/TriangleMesh.h"

namespace aokit {

class HullRadius {
 public:
  // Support of the mesh's vertices relative to `centre`, which must lie inside their hull.
  HullRadius(const TriangleMesh& mesh, const glm::dvec3& centre, int directions = 4096, int threads = 0);
  double operator()(const glm::dvec3& unitDirection) const;
  // Largest vertex distance from the centre (the bounding sphere's radius).
  double boundingRadius() const { return boundingRadius_; }

 private:
  std::vector<glm::dvec3> normals_;
  std::vector<double> support_;
  double boundingRadius_ = 0.0;
};

// Area-weighted mean of the triangle centroids: a convex combination of vertices, so always
// inside their hull (the bounding-box centre need not be, e.g. for an L shape).
glm::dvec3 surfaceCentroid(const TriangleMesh& mesh);

}  // namespace aokit
