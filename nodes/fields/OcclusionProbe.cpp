#include "fields/OcclusionProbe.h"

#include "reference/EmbreeScene.h"
#include "reference/Falloff.h"
#include "reference/SurfaceRay.h"

namespace aokit {

OcclusionProbe::OcclusionProbe(const EmbreeScene& scene, double radius, Falloff falloff,
                               std::vector<glm::dvec3> directions)
    : scene_(scene),
      radius_(radius),
      falloff_(falloff),
      stream_(rtcGetDeviceProperty(scene.device(), RTC_DEVICE_PROPERTY_RAY_STREAM_SUPPORTED) != 0),
      base_(std::move(directions)),
      turned_(base_.size()),
      weights_(base_.size(), 0.0) {
  if (falloff_ == Falloff::Binary)
    rays_.resize(base_.size());
  else
    hits_.resize(base_.size());
}

void OcclusionProbe::trace(const glm::dvec3& x, const glm::dmat3& rotation) {
  const glm::vec3 origin(x);
  const float tfar = static_cast<float>(radius_);
  const int n = size();
  for (int j = 0; j < n; ++j) turned_[j] = rotation * base_[j];
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  if (falloff_ == Falloff::Binary) {
    for (int j = 0; j < n; ++j) rays_[j] = makeRayHit(origin, glm::vec3(turned_[j]), 0.0f, tfar).ray;
    if (stream_)
      rtcOccluded1M(scene_.scene(), &ctx, rays_.data(), n, sizeof(RTCRay));
    else
      for (int j = 0; j < n; ++j) rtcOccluded1(scene_.scene(), &ctx, &rays_[j]);
    for (int j = 0; j < n; ++j) weights_[j] = rays_[j].tfar < 0.0f ? 1.0 : 0.0;  // occluded: tfar = -inf
  } else {
    for (int j = 0; j < n; ++j) hits_[j] = makeRayHit(origin, glm::vec3(turned_[j]), 0.0f, tfar);
    if (stream_)
      rtcIntersect1M(scene_.scene(), &ctx, hits_.data(), n, sizeof(RTCRayHit));
    else
      for (int j = 0; j < n; ++j) rtcIntersect1(scene_.scene(), &ctx, &hits_[j]);
    for (int j = 0; j < n; ++j)
      weights_[j] = hits_[j].hit.geomID == RTC_INVALID_GEOMETRY_ID
                        ? 0.0
                        : falloffWeight(falloff_, hits_[j].ray.tfar, radius_);  // unit directions: tfar = d
  }
}

}  // namespace aokit

#include "core/Geometry.h"
#include "core/Group.h"

namespace aokit {

std::unique_ptr<EmbreeScene> makeOccluderScene(const TriangleMesh& mesh) {
  Group root;
  // Non-owning: the scene copies the vertices into Embree's buffers during construction.
  std::shared_ptr<const TriangleMesh> view(&mesh, [](const TriangleMesh*) {});
  root.addChild(std::make_shared<Geometry>(view, glm::vec3(1.0f)));
  return std::make_unique<EmbreeScene>(root);
}

}  // namespace aokit
