#pragma once
// The occluders of a scene graph as one Embree scene, in world space: the reference's ray tracer.
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include "core/Bounds.h"
#include "core/Node.h"
#include "core/TriangleMesh.h"

namespace aokit {

struct EmbreeSceneStats {
  double buildSeconds = 0.0;      // device setup, world transform, upload and BVH build
  std::size_t memoryBytes = 0;    // bytes the Embree device holds (buffers + BVH), from its memory monitor
  std::size_t triangles = 0;
  std::size_t instances = 0;
};

// One Embree geometry per GeometryInstance (geomID = index into instances()): vertices are
// transformed to world in double and then rounded to float, so no instancing and no per-ray
// transform; repeated meshes cost memory, which the stats report. Built with RTC_BUILD_QUALITY_HIGH
// and RTC_SCENE_FLAG_ROBUST (watertight: no ray slips through the edges of a closed mesh).
class EmbreeScene {
 public:
  struct Instance {
    std::shared_ptr<const TriangleMesh> mesh;
    glm::dmat4 world{1.0};
    glm::vec3 albedo{0.8f};  // the Geometry's (the ambient transfer reference reads it)
  };

  // Collects collectInstances(root, mask) and builds the BVH. Throws std::runtime_error on an
  // Embree error or an invalid mesh (TriangleMesh::validate()).
  explicit EmbreeScene(Node& root, std::uint32_t mask = kCastsAO);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  RTCScene scene() const { return scene_; }
  RTCDevice device() const { return device_; }
  const std::vector<Instance>& instances() const { return instances_; }
  const EmbreeSceneStats& stats() const { return stats_; }
  // World bounds of every occluder; extent() is their diagonal (0 for an empty scene).
  const Bounds& bounds() const { return bounds_; }
  double extent() const { return bounds_.diagonal(); }
  // Widest ray packet (1, 4, 8 or 16) this Embree build traces natively on this CPU.
  int nativePacketWidth() const;

  // Throws std::runtime_error with the message of the first device error since the last check
  // (errors are reported by Embree's callback from any thread).
  void throwIfError(const std::string& context) const;

 private:
  static void onError(void* self, RTCError code, const char* message);
  static bool onMemory(void* self, ssize_t bytes, bool post);

  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
  std::vector<Instance> instances_;
  Bounds bounds_;
  EmbreeSceneStats stats_;
  std::atomic<long long> deviceBytes_{0};
  mutable std::mutex errorMutex_;
  mutable std::string error_;
};

}  // namespace aokit
