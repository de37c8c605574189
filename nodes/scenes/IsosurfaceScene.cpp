// "isosurface": two nested contours of an analytic field, as a scientific viewer shows them (one
// vtkFlyingEdges3D output with both values, gradient normals, one actor). The field is a sum of
// Gaussian blobs on a 128^3 grid; blobs near the domain's faces cut the outer contour open there,
// so the eye looks through the openings onto the inner contour. Thin necks join the outer blobs.
// The failure cases this brings: a lone mesh that occludes itself (no other occluder for fields),
// nested sheets hidden from screen space, open single-sided edges, 178,760 triangles.
#include <cmath>

#include <vtkFlyingEdges3D.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "render/PolyDataMesh.h"
#include "scenes/SceneBuilders.h"
#include "scenes/SceneBuilding.h"

namespace aokit {
namespace {

constexpr int kGrid = 128;           // samples per axis over the domain [-1.6, 1.6]^3
constexpr double kHalfSize = 1.6;
constexpr double kOuterLevel = 0.30;
constexpr double kInnerLevel = 0.75;

struct Blob {
  glm::dvec3 centre;
  double width;   // Gaussian standard deviation
  double weight;
};

// Fixed blobs: three near faces of the domain (their outer contour leaves it), two inside.
const Blob kBlobs[] = {
    {{-1.2, -0.3, -0.2}, 0.55, 1.0}, {{0.9, 0.5, 0.1}, 0.6, 1.0},   {{0.2, -1.3, 0.9}, 0.45, 0.9},
    {{0.1, 0.3, -1.5}, 0.5, 0.95},   {{1.6, -1.1, -0.6}, 0.5, 0.9}, {{-0.6, 1.5, 1.3}, 0.5, 0.85},
};

double field(const glm::dvec3& p) {
  double f = 0.0;
  for (const Blob& b : kBlobs) {
    const glm::dvec3 d = p - b.centre;
    f += b.weight * std::exp(-glm::dot(d, d) / (2.0 * b.width * b.width));
  }
  return f;
}

std::shared_ptr<TriangleMesh> contourMesh() {
  vtkNew<vtkImageData> image;
  image->SetDimensions(kGrid, kGrid, kGrid);
  const double spacing = 2.0 * kHalfSize / (kGrid - 1);
  image->SetSpacing(spacing, spacing, spacing);
  image->SetOrigin(-kHalfSize, -kHalfSize, -kHalfSize);
  vtkNew<vtkFloatArray> values;
  values->SetName("field");
  values->SetNumberOfTuples(static_cast<vtkIdType>(kGrid) * kGrid * kGrid);
  vtkIdType id = 0;
  for (int k = 0; k < kGrid; ++k)
    for (int j = 0; j < kGrid; ++j)
      for (int i = 0; i < kGrid; ++i)
        values->SetValue(id++, static_cast<float>(field(glm::dvec3(-kHalfSize) + spacing * glm::dvec3(i, j, k))));
  image->GetPointData()->SetScalars(values);

  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(image);
  contour->SetNumberOfContours(2);
  contour->SetValue(0, kOuterLevel);
  contour->SetValue(1, kInnerLevel);
  contour->ComputeNormalsOn();  // gradient normals, as ParaView's Contour gives them
  contour->ComputeScalarsOff();
  contour->Update();
  return std::make_shared<TriangleMesh>(triangleMeshOf(*contour->GetOutput()));
}

}  // namespace

Scene makeIsosurfaceScene() {
  Scene scene;
  addPlaced(*scene.root, contourMesh(), glm::dmat4(1.0), glm::vec3(kDefaultAlbedo), "contours");
  scene.camera.position = {4.6, -7.5, 5.0};
  scene.camera.focalPoint = {0.0, 0.0, 0.0};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 30.0;
  scene.root->setAORadius(0.5);  // an eighth of the domain: the blobs' necks and the gap between the contours
  return scene;
}

}  // namespace aokit
