#include "render/GBufferLayout.h"

#include <vtkType.h>
#include <vtk_glew.h>

namespace aokit {

std::vector<GBufferTargetFormat> gbufferLayout(const GBufferOptions& o) {
  std::vector<GBufferTargetFormat> out{{GBufferTarget::Color, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, VTK_UNSIGNED_CHAR, 4}};
  if (o.lean) {
    out.push_back({GBufferTarget::Normal, GL_RGB10_A2, GL_RGBA, GL_UNSIGNED_BYTE, 4, VTK_UNSIGNED_CHAR, 4});
  } else {
    out.push_back({GBufferTarget::Position, GL_RGBA32F, GL_RGBA, GL_FLOAT, 4, VTK_FLOAT, 16});
    out.push_back({GBufferTarget::Normal, GL_RGBA32F, GL_RGBA, GL_FLOAT, 4, VTK_FLOAT, 16});
  }
  out.push_back({GBufferTarget::Flags, GL_R8, GL_RED, GL_UNSIGNED_BYTE, 1, VTK_UNSIGNED_CHAR, 1});
  if (o.bakedAO) out.push_back({GBufferTarget::BakedAO, GL_R16F, GL_RED, GL_FLOAT, 1, VTK_FLOAT, 2});
  if (o.instanceIds) out.push_back({GBufferTarget::InstanceId, GL_R32F, GL_RED, GL_FLOAT, 1, VTK_FLOAT, 4});
  return out;
}

int gbufferAttachment(const GBufferOptions& o, GBufferTarget t) {
  const std::vector<GBufferTargetFormat> layout = gbufferLayout(o);
  for (std::size_t i = 0; i < layout.size(); ++i)
    if (layout[i].target == t) return static_cast<int>(i);
  return -1;
}

std::size_t gbufferBytesPerPixel(const GBufferOptions& o) {
  std::size_t bytes = 4;  // depth, 32-bit float
  for (const GBufferTargetFormat& f : gbufferLayout(o)) bytes += f.bytes;
  return bytes;
}

}  // namespace aokit
