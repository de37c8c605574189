#include "reference/EmbreeScene.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "core/Geometry.h"
#include "core/NodeVisitor.h"

namespace aokit {

namespace {

const char* errorName(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE: return "no error";
    case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
    case RTC_ERROR_CANCELLED: return "cancelled";
    default: return "unknown error";
  }
}

}  // namespace

void EmbreeScene::onError(void* self, RTCError code, const char* message) {
  auto* s = static_cast<EmbreeScene*>(self);
  std::lock_guard<std::mutex> lock(s->errorMutex_);
  if (s->error_.empty()) s->error_ = std::string(errorName(code)) + (message ? std::string(": ") + message : "");
}

bool EmbreeScene::onMemory(void* self, ssize_t bytes, bool /*post*/) {
  static_cast<EmbreeScene*>(self)->deviceBytes_ += bytes;
  return true;  // never veto an allocation: the OS is the limit
}

void EmbreeScene::throwIfError(const std::string& context) const {
  std::lock_guard<std::mutex> lock(errorMutex_);
  if (error_.empty()) return;
  std::string message = "Embree error (" + context + "): " + error_;
  error_.clear();
  throw std::runtime_error(message);
}

EmbreeScene::EmbreeScene(Node& root, std::uint32_t mask) {
  const auto start = std::chrono::steady_clock::now();
  device_ = rtcNewDevice(nullptr);
  if (!device_)
    throw std::runtime_error(std::string("Embree error (rtcNewDevice): ") + errorName(rtcGetDeviceError(nullptr)));
  rtcSetDeviceErrorFunction(device_, &EmbreeScene::onError, this);
  rtcSetDeviceMemoryMonitorFunction(device_, &EmbreeScene::onMemory, this);

  try {
    scene_ = rtcNewScene(device_);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);
    // Watertight traversal: without it ~1 ray in 10^6 slipped between the triangles of a closed
    // sphere (a reference must not leak); the cost was within this machine's timing noise.
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    for (const GeometryInstance& gi : collectInstances(root, mask)) {
      const auto& mesh = gi.geometry->mesh();
      if (!mesh || mesh->empty()) continue;
      mesh->validate();
      RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                            3 * sizeof(float), mesh->positions.size()));
      auto* t = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), mesh->triangles.size()));
      if (!v || !t) {
        rtcReleaseGeometry(geom);
        throwIfError("geometry buffers");
        throw std::runtime_error("Embree error (geometry buffers): allocation failed");
      }
      for (std::size_t i = 0; i < mesh->positions.size(); ++i) {
        // Transform in double, round once: world positions as exact as float allows.
        const glm::dvec3 w(gi.world * glm::dvec4(glm::dvec3(mesh->positions[i]), 1.0));
        v[3 * i + 0] = static_cast<float>(w.x);
        v[3 * i + 1] = static_cast<float>(w.y);
        v[3 * i + 2] = static_cast<float>(w.z);
        bounds_.extend(glm::dvec3(v[3 * i], v[3 * i + 1], v[3 * i + 2]));
      }
      for (std::size_t i = 0; i < mesh->triangles.size(); ++i) {
        t[3 * i + 0] = mesh->triangles[i].x;
        t[3 * i + 1] = mesh->triangles[i].y;
        t[3 * i + 2] = mesh->triangles[i].z;
      }
      rtcCommitGeometry(geom);
      rtcAttachGeometryByID(scene_, geom, static_cast<unsigned>(instances_.size()));
      rtcReleaseGeometry(geom);
      instances_.push_back({mesh, gi.world, gi.geometry->albedo()});
      stats_.triangles += mesh->triangles.size();
    }
    rtcCommitScene(scene_);
    throwIfError("building the scene");
  } catch (...) {
    if (scene_) rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
    throw;
  }
  stats_.instances = instances_.size();
  stats_.memoryBytes = static_cast<std::size_t>(std::max(0LL, deviceBytes_.load()));
  stats_.buildSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

EmbreeScene::~EmbreeScene() {
  rtcReleaseScene(scene_);
  rtcReleaseDevice(device_);
}

int EmbreeScene::nativePacketWidth() const {
  if (rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_NATIVE_RAY16_SUPPORTED)) return 16;
  if (rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_NATIVE_RAY8_SUPPORTED)) return 8;
  if (rtcGetDeviceProperty(device_, RTC_DEVICE_PROPERTY_NATIVE_RAY4_SUPPORTED)) return 4;
  return 1;
}

}  // namespace aokit
