#pragma once
// Rays from one point in space over the whole sphere, each weighted by the falloff k(d) of its first
// hit within the AO radius R (0 for a miss): the bakes' one measurement. Means over the rays give
// the falloff-weighted solid angle and direction moment of the radial fields and the cosine-
// weighted half-sphere terms of the grid fields.
//
// One probe per worker thread (it owns its ray buffers). Binary falloff needs only occlusion rays
// (rtcOccluded1M, tfar = R); the others need the hit distance (rtcIntersect1M).
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "core/AOScene.h"

namespace aokit {

class EmbreeScene;

class OcclusionProbe {
 public:
  // directions: unit vectors spread evenly over the sphere (SphereDirections.h).
  OcclusionProbe(const EmbreeScene& scene, double radius, Falloff falloff, std::vector<glm::dvec3> directions);

  // Traces the directions turned by `rotation` from x; afterwards direction(j) and weight(j) hold
  // each ray's world direction and k(d) in [0, 1].
  void trace(const glm::dvec3& x, const glm::dmat3& rotation);
  int size() const { return static_cast<int>(base_.size()); }
  const glm::dvec3& direction(int j) const { return turned_[j]; }
  double weight(int j) const { return weights_[j]; }

 private:
  const EmbreeScene& scene_;
  double radius_;
  Falloff falloff_;
  bool stream_;
  std::vector<glm::dvec3> base_, turned_;
  std::vector<double> weights_;
  std::vector<RTCRay> rays_;
  std::vector<RTCRayHit> hits_;
};

}  // namespace aokit

#include <memory>

#include "core/TriangleMesh.h"

namespace aokit {

// An Embree scene holding only this mesh, untransformed (the occluder's own coordinates). The mesh
// must outlive the scene's use in a bake (it is not copied).
std::unique_ptr<EmbreeScene> makeOccluderScene(const TriangleMesh& mesh);

}  // namespace aokit
