#pragma once
// The G-buffer's targets as one table (GBufferPass.h says what each holds): which targets a
// configuration has, in attachment order, with their GL formats and bytes. Everything that
// allocates, attaches, resizes, counts or releases targets goes through it.
#include <cstddef>
#include <vector>

namespace aokit {

enum class GBufferTarget { Color, Position, Normal, Flags, BakedAO, InstanceId };
constexpr int kGBufferTargets = 6;

struct GBufferTargetFormat {
  GBufferTarget target;
  unsigned internalFormat, format, type;
  int components, vtkType;
  std::size_t bytes;  // per texel
};

struct GBufferOptions {
  bool lean = false;         // no position target; the normal packed in RGB10_A2
  bool bakedAO = false;      // the R16F baked-AO target
  bool instanceIds = false;  // the R32F instance-id target
  bool facetNormals = false; // the normal written is the facet's, not VTK's shading normal
};

// The colour targets of a configuration in attachment order (colour first), depth not included.
std::vector<GBufferTargetFormat> gbufferLayout(const GBufferOptions& o);
// The attachment index of a target in that layout, -1 when absent.
int gbufferAttachment(const GBufferOptions& o, GBufferTarget t);
// Bytes per pixel of every target, the 32-bit float depth included.
std::size_t gbufferBytesPerPixel(const GBufferOptions& o);

}  // namespace aokit
