#include "vtkAOKitReference.h"

#include <cmath>
#include <memory>
#include <stdexcept>

#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkObjectFactory.h>
#include <vtkRenderer.h>

#include "core/AOScene.h"
#include "core/Geometry.h"
#include "core/Transform.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"
#include "reference/Falloff.h"
#include "reference/Metrics.h"
#include "reference/PrimarySamples.h"
#include "render/PolyDataMesh.h"
#include "render/PropMeshes.h"

vtkStandardNewMacro(vtkAOKitReference);

namespace {
// The renderer's casting meshes as a scene graph the reference reads.
std::shared_ptr<aokit::AOScene> casterScene(vtkRenderer* renderer) {
  auto root = std::make_shared<aokit::AOScene>();
  aokit::PropMeshes meshes("reference");
  for (const aokit::PropMesh& m : meshes.collect(renderer)) {
    auto mesh = std::make_shared<aokit::TriangleMesh>(aokit::triangleMeshOf(*m.poly));
    if (mesh->empty()) continue;
    auto place = std::make_shared<aokit::Transform>();
    place->setMatrix(m.modelToWorld);
    place->addChild(std::make_shared<aokit::Geometry>(mesh, glm::vec3(0.8f)));
    root->addChild(place);
  }
  return root;
}

aokit::AOBuffer bufferOf(vtkFloatArray* a, int width, int height) {
  if (!a || width < 1 || height < 1 || a->GetNumberOfComponents() != 1 ||
      a->GetNumberOfTuples() != static_cast<vtkIdType>(width) * height)
    throw std::invalid_argument("an AO array must hold width x height values, one per pixel");
  aokit::AOBuffer b;
  b.resize(width, height);
  for (std::size_t i = 0; i < b.ao.size(); ++i) {
    const float v = a->GetValue(static_cast<vtkIdType>(i));
    b.covered[i] = std::isfinite(v) && v >= 0.0f;
    b.ao[i] = b.covered[i] ? v : 0.0f;
  }
  return b;
}
}  // namespace

bool vtkAOKitReference::Compute(vtkRenderer* renderer, vtkFloatArray* ao, int size[2]) {
  try {
    if (!renderer || !ao) throw std::invalid_argument("reference: needs a renderer and an array");
    if (Samples < 1 || Samples > 65536) throw std::invalid_argument("reference: samples must be in 1..65536");
    if (!std::isfinite(Radius) || Radius <= 0.0) throw std::invalid_argument("reference: the radius must be > 0");
    aokit::ReferenceOptions o;
    o.samples = Samples;
    o.radius = Radius;
    o.falloff = aokit::parseFalloff(Falloff);
    o.seed = static_cast<std::uint64_t>(Seed);
    o.progress = [this](double f) { InvokeEvent(vtkCommand::ProgressEvent, &f); };
    vtkCamera* c = renderer->GetActiveCamera();
    const int* s = renderer->GetSize();
    if (s[0] < 1 || s[1] < 1) throw std::invalid_argument("reference: the renderer has no size yet (render once first)");
    auto root = casterScene(renderer);
    if (root->childCount() == 0) throw std::invalid_argument("reference: the renderer shows no casting geometry");
    aokit::Camera cam;
    cam.position = glm::dvec3(c->GetPosition()[0], c->GetPosition()[1], c->GetPosition()[2]);
    cam.focalPoint = glm::dvec3(c->GetFocalPoint()[0], c->GetFocalPoint()[1], c->GetFocalPoint()[2]);
    cam.viewUp = glm::dvec3(c->GetViewUp()[0], c->GetViewUp()[1], c->GetViewUp()[2]);
    cam.viewAngleDeg = c->GetViewAngle();
    cam.parallel = c->GetParallelProjection() != 0;
    cam.parallelScale = c->GetParallelScale();
    const aokit::EmbreeScene scene(*root);
    const aokit::SurfaceSamples hits = aokit::castPrimarySamples(scene, cam, s[0], s[1]);
    const aokit::AOBuffer out = aokit::computeReferenceAO(scene, hits, o);
    ao->SetNumberOfComponents(1);
    ao->SetNumberOfTuples(static_cast<vtkIdType>(out.ao.size()));
    for (std::size_t i = 0; i < out.ao.size(); ++i)
      ao->SetValue(static_cast<vtkIdType>(i), out.covered[i] ? out.ao[i] : -1.0f);
    size[0] = s[0];
    size[1] = s[1];
    LastError.clear();
    return true;
  } catch (const std::exception& e) {
    LastError = e.what();
    return false;
  }
}

bool vtkAOKitReference::Compare(vtkFloatArray* test, vtkFloatArray* reference, int width, int height, double out[5]) {
  try {
    const aokit::AOErrorMetrics m = aokit::compareAO(bufferOf(test, width, height), bufferOf(reference, width, height));
    out[0] = m.rmse;
    out[1] = m.meanAbsError;
    out[2] = m.p99AbsError;
    out[3] = m.ssim;
    out[4] = static_cast<double>(m.pixels);
    LastError.clear();
    return true;
  } catch (const std::exception& e) {
    LastError = e.what();
    return false;
  }
}
