#pragma once
// An OSMesa core-profile context with its own colour buffer. Kept apart from VTK code because
// osmesa.h and GLEW's headers cannot share a translation unit.
#include <cstdint>
#include <vector>

namespace aokit {

class OSMesaContext {
 public:
  OSMesaContext(int width, int height);  // throws std::runtime_error when OSMesa refuses
  ~OSMesaContext();
  OSMesaContext(const OSMesaContext&) = delete;
  OSMesaContext& operator=(const OSMesaContext&) = delete;

  void makeCurrent();
  bool isCurrent() const;

 private:
  void* context_ = nullptr;
  std::vector<std::uint8_t> buffer_;  // OSMesa's default framebuffer; VTK draws to its own FBO
  int width_, height_;
};

}  // namespace aokit
