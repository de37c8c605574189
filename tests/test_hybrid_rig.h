#pragma once
// Shared by the HybridPass tests: a built-in scene rendered offscreen with a technique, its
// reference, the surface samples the pass itself saw (its lean G-buffer, in the float arithmetic
// of DeferredCommon.glsl), and the differences between two AO buffers.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include <gtest/gtest.h>

#include "headless/FrameCapture.h"
#include "headless/OffscreenWindow.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "render/SceneRenderer.h"
#include "scenes/BuiltinScenes.h"
#include "voxel/HybridPass.h"
#include "voxel/HybridTechnique.h"

namespace aokit {
namespace hybridtest {

constexpr int kW = 256, kH = 192;

struct SceneRig {
  Scene scene;
  OffscreenWindow window{kW, kH};
  SceneRenderer renderer{window.renderer()};
  SurfaceSamples surfaces;

  explicit SceneRig(const std::string& name) : scene(makeBuiltinScene(name)) {
    renderer.setScene(scene.root);
    renderer.sync();
    renderer.applyCamera(scene.camera);
    surfaces = captureSurfaces(window, renderer);
  }
  AOBuffer reference(int samples = 64) {
    EmbreeScene embree(*scene.root);
    ReferenceOptions opt = sceneReferenceOptions(*scene.root, samples, 1);
    return computeReferenceAO(embree, surfaces, opt);
  }
  std::shared_ptr<HybridTechnique> attach(const HybridSettings& s) {
    auto t = std::make_shared<HybridTechnique>(s);
    scene.root->setTechnique(t);
    renderer.sync();
    return t;
  }
  AOBuffer render(HybridTechnique& t) {
    window.render();
    window.makeCurrent();
    AOBuffer out;
    out.resize(kW, kH);
    out.covered = surfaces.covered;
    EXPECT_TRUE(t.readAO(window.renderer(), out.ao));
    for (std::size_t i = 0; i < out.ao.size(); ++i)
      if (!out.covered[i]) out.ao[i] = 0.0f;
    return out;
  }
  void detach() {
    scene.root->setTechnique(nullptr);
    renderer.sync();
  }
};

// The surface samples the pass itself saw: its lean G-buffer (window depth and the packed normal)
// turned into world positions and normals with the float arithmetic of DeferredCommon.glsl and
// HybridMarchFS.glsl, so that the CPU oracle marches from the same points.
inline SurfaceSamples leanSurfaces(HybridPass* pass, vtkRenderer* renderer) {
  GBufferPass* g = pass->GetGBufferPass();
  const int w = g->GetWidth(), h = g->GetHeight();
  std::vector<float> depth(static_cast<std::size_t>(w) * h), packed(static_cast<std::size_t>(w) * h * 4);
  glGetTextureImage(g->GetDepthTexture()->GetHandle(), 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                    static_cast<GLsizei>(depth.size() * 4), depth.data());
  glGetTextureImage(g->GetNormalTexture()->GetHandle(), 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(packed.size() * 4),
                    packed.data());
  vtkMatrix4x4* P = g->GetProjection();
  glm::vec4 clipX, clipY, clipW;
  for (int j = 0; j < 4; ++j) {
    clipX[j] = static_cast<float>(P->GetElement(0, j));
    clipY[j] = static_cast<float>(P->GetElement(1, j));
    clipW[j] = static_cast<float>(P->GetElement(3, j));
  }
  const float A = static_cast<float>(P->GetElement(2, 2)), B = static_cast<float>(P->GetElement(2, 3)),
              C = static_cast<float>(P->GetElement(3, 2)), D = static_cast<float>(P->GetElement(3, 3));
  vtkMatrix4x4* view = renderer->GetActiveCamera()->GetModelViewTransformMatrix();
  glm::dmat4 worldToView;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) worldToView[j][i] = view->GetElement(i, j);
  const glm::mat4 viewToWorld(glm::inverse(worldToView));
  SurfaceSamples s;
  s.resize(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = s.index(x, y);
      const float* pn = &packed[4 * i];
      if (!(pn[3] > 0.5f)) continue;
      const float ndcZ = 2.0f * depth[i] - 1.0f;
      const float z = (B - ndcZ * D) / (ndcZ * C - A);
      const glm::vec2 ndc = (glm::vec2(x, y) + 0.5f) / glm::vec2(w, h) * 2.0f - 1.0f;
      const float ww = clipW.z * z + clipW.w;
      const glm::vec3 pv((ndc.x * ww - clipX.z * z - clipX.w) / clipX.x, (ndc.y * ww - clipY.z * z - clipY.w) / clipY.y, z);
      s.position[i] = glm::vec3(viewToWorld * glm::vec4(pv, 1.0f));
      s.normal[i] = glm::normalize(glm::mat3(viewToWorld) * glm::normalize(glm::vec3(pn[0], pn[1], pn[2]) * 2.0f - 1.0f));
      s.covered[i] = 1;
    }
  return s;
}

struct Difference {
  double mean = 0.0, p99 = 0.0, max = 0.0, over05 = 0.0;
};

inline Difference differ(const AOBuffer& a, const AOBuffer& b) {
  std::vector<double> d;
  for (std::size_t i = 0; i < a.ao.size(); ++i)
    if (a.covered[i] && b.covered[i]) d.push_back(std::abs(double(a.ao[i]) - b.ao[i]));
  Difference r;
  if (d.empty()) return r;
  std::sort(d.begin(), d.end());
  for (double v : d) r.mean += v;
  r.mean /= d.size();
  r.p99 = d[static_cast<std::size_t>(0.99 * (d.size() - 1))];
  r.max = d.back();
  r.over05 = double(std::count_if(d.begin(), d.end(), [](double v) { return v > 0.05; })) / d.size();
  return r;
}

}  // namespace hybridtest
}  // namespace aokit
