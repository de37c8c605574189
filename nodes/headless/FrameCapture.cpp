#include "headless/FrameCapture.h"

#include <stdexcept>

#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderPass.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include "render/GBufferPass.h"
#include "headless/OffscreenWindow.h"
#include "render/SceneRenderer.h"

namespace aokit {

namespace {

// While alive: the renderer draws through `pass`; the pass it had (the technique's, which stays
// attached with its GPU state) is put back on scope exit, exceptions included.
class PassSwap {
 public:
  PassSwap(vtkRenderer* renderer, vtkRenderPass* pass) : renderer_(renderer), previous_(renderer->GetPass()) {
    renderer_->SetPass(pass);
  }
  ~PassSwap() { renderer_->SetPass(previous_); }
  PassSwap(const PassSwap&) = delete;
  PassSwap& operator=(const PassSwap&) = delete;

 private:
  vtkRenderer* renderer_;
  vtkSmartPointer<vtkRenderPass> previous_;
};

}  // namespace

SurfaceSamples captureSurfaces(OffscreenWindow& window, SceneRenderer& scene, bool facetNormals) {
  if (!scene.scene()) throw std::logic_error("captureSurfaces: no scene");
  vtkNew<GBufferPass> gbuffer;
  gbuffer->SetFacetNormals(facetNormals);
  std::vector<float> posVC, nrmVC;
  std::vector<std::uint8_t> flags;
  vtkRenderer* renderer = window.renderer();
  const ShadingMode mode = scene.shadingMode();
  scene.setShadingMode(ShadingMode::Lit);  // lighting on: VTK then provides vertexVC and normals
  scene.sync();
  {
    PassSwap swap(renderer, gbuffer);
    window.render();
    window.makeCurrent();
    if (!gbuffer->ReadBack(posVC, nrmVC) || !gbuffer->ReadFlags(flags))
      throw std::runtime_error("G-buffer read-back failed");
  }
  scene.setShadingMode(mode);
  scene.sync();
  gbuffer->ReleaseGraphicsResources(window.window());

  // VTK's model-view matrix maps world to view coordinates (row-major, column vectors).
  vtkMatrix4x4* viewM = renderer->GetActiveCamera()->GetModelViewTransformMatrix();
  glm::dmat4 view;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) view[c][r] = viewM->GetElement(r, c);
  const glm::dmat4 toWorld = glm::inverse(view);
  const glm::dmat3 rotToWorld(toWorld);  // the view transform is rigid: normals rotate like points

  SurfaceSamples s;
  s.resize(window.width(), window.height());
  for (std::size_t i = 0; i < s.pixelCount(); ++i) {
    const float* p = &posVC[i * 4];
    const float* n = &nrmVC[i * 4];
    if (p[3] <= 0.5f) continue;
    s.covered[i] = 1;
    s.receives[i] = (flags[i] & 2) != 0;  // ActorKeys.h: 1 covered + 2 receives + 4 casts
    s.position[i] = glm::vec3(toWorld * glm::dvec4(p[0], p[1], p[2], 1.0));
    s.normal[i] = glm::vec3(glm::normalize(rotToWorld * glm::dvec3(n[0], n[1], n[2])));
  }
  return s;
}

AOBuffer captureAO(OffscreenWindow& window, SceneRenderer& scene, const std::vector<std::uint8_t>& coverage) {
  const std::size_t n = static_cast<std::size_t>(window.width()) * window.height();
  if (coverage.size() != n) throw std::invalid_argument("captureAO: coverage does not match the window size");
  AOBuffer out;
  out.resize(window.width(), window.height());
  out.covered = coverage;
  // The frame as the method renders it (a transfer method reads the lit colour as albedo); only a
  // technique that cannot hand over its AO is rendered again ambient-only and white.
  scene.sync();
  window.render();
  const auto& technique = scene.scene()->technique();
  if (!(technique && technique->readAO(window.renderer(), out.ao))) {
    const ShadingMode mode = scene.shadingMode();
    scene.setShadingMode(ShadingMode::AOOnly);
    scene.sync();
    window.render();
    const RGBAImage img = window.readColor();
    for (std::size_t i = 0; i < n; ++i) out.ao[i] = 1.0f - img.pixels[i * 4] / 255.0f;
    scene.setShadingMode(mode);
    scene.sync();
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!out.covered[i]) out.ao[i] = 0.0f;
  return out;
}

}  // namespace aokit
