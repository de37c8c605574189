#include "headless/OSMesaContext.h"

#include <GL/osmesa.h>

#include <stdexcept>

namespace aokit {

OSMesaContext::OSMesaContext(int width, int height) : width_(width), height_(height) {
  const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_STENCIL_BITS, 0,
                         OSMESA_ACCUM_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION, 3, OSMESA_CONTEXT_MINOR_VERSION, 3, 0};
  context_ = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!context_) throw std::runtime_error("could not create an OSMesa core-profile 3.3 context");
  buffer_.resize(static_cast<std::size_t>(width) * height * 4);
}

OSMesaContext::~OSMesaContext() {
  if (context_) OSMesaDestroyContext(static_cast<::OSMesaContext>(context_));
}

void OSMesaContext::makeCurrent() {
  if (!OSMesaMakeCurrent(static_cast<::OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE, width_, height_))
    throw std::runtime_error("OSMesaMakeCurrent failed");
}

bool OSMesaContext::isCurrent() const { return context_ && OSMesaGetCurrentContext() == context_; }

}  // namespace aokit
