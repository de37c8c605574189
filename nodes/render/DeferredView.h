#pragma once
// DeferredAOPass's per-renderer state (private to the pass's sources).
#include <cstddef>

#include <vtkNew.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkRenderPass.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextureObject.h>
#include <vtkWeakPointer.h>

#include "render/AOAccumulator.h"
#include "render/DeferredAOPass.h"
#include "render/DeferredFrame.h"
#include "render/DeferredUpsampler.h"
#include "render/GBufferPass.h"
#include "render/Textures.h"

namespace aokit {

// One renderer's share of the pass: its G-buffer, AO targets and last frame, so that one pass can
// serve several renderers (viewports, views) and read each one's AO back.
struct DeferredAOPass::View {
  vtkWeakPointer<vtkRenderer> renderer;
  vtkNew<GBufferPass> gbuffer;
  vtkSmartPointer<vtkOpenGLFramebufferObject> framebuffer;
  vtkSmartPointer<vtkTextureObject> aoTarget, zTarget, resultTarget;
  DeferredUpsampler upsampler;
  AOAccumulator accumulator;
  DeferredFrame frame;
  vtkSmartPointer<vtkRenderPass> opaque;  // multisampled windows: VTK's opaque steps, drawn again
  vtkTextureObject* result = nullptr;  // the family's final AO
  bool hasFrame = false;

  std::size_t memoryBytes() const {
    return gbuffer->MemoryBytes() + textureBytes(aoTarget) + textureBytes(zTarget) + textureBytes(resultTarget) +
           upsampler.memoryBytes() +
           accumulator.memoryBytes();
  }
  void release(vtkWindow* w) {
    gbuffer->ReleaseGraphicsResources(w);
    if (opaque) opaque->ReleaseGraphicsResources(w);
    opaque = nullptr;
    upsampler.release(w);
    accumulator.release(w);
    aoTarget = zTarget = resultTarget = nullptr;
    framebuffer = nullptr;
    result = nullptr;
    frame = DeferredFrame{};
    hasFrame = false;
  }
};

}  // namespace aokit
