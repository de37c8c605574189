// "streamlines": tubes around streamlines of the ABC flow (Arnold-Beltrami-Childress, A = 1,
// B = sqrt(2/3), C = sqrt(1/3)) in its periodic box, as a flow viewer shows them: RK4 lines from a
// grid of seeds, both directions, stopped at the box, through vtkTubeFilter (capped, 10 sides) into
// one actor. Chaotic lines weave past each other at every distance, so the occluders are many thin
// cylinders: thin features between grid steps for voxels, one self-occluding mesh for fields.
#include <cmath>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTubeFilter.h>

#include "render/PolyDataMesh.h"
#include "scenes/SceneBuilders.h"
#include "scenes/SceneBuilding.h"

namespace aokit {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kWorldHalfSize = 2.0;  // the flow's box [0, 2 pi]^3 is drawn as [-2, 2]^3
constexpr double kStep = 0.04;          // RK4 step in flow time (the speed is about 1.4)
constexpr int kMaxSteps = 400;          // per direction
constexpr int kSeedsPerSide = 8;        // seeds on an 8 x 8 grid in the plane z = pi
constexpr double kTubeRadius = 0.03;    // world units

glm::dvec3 abcVelocity(const glm::dvec3& p) {
  const double a = 1.0, b = std::sqrt(2.0 / 3.0), c = std::sqrt(1.0 / 3.0);
  return {a * std::sin(p.z) + c * std::cos(p.y), b * std::sin(p.x) + a * std::cos(p.z),
          c * std::sin(p.y) + b * std::cos(p.x)};
}

bool insideBox(const glm::dvec3& p) {
  return p.x >= 0.0 && p.y >= 0.0 && p.z >= 0.0 && p.x <= kTwoPi && p.y <= kTwoPi && p.z <= kTwoPi;
}

// RK4 from `seed` along `direction` (+1 or -1) until the box is left or kMaxSteps are taken.
std::vector<glm::dvec3> traceHalf(const glm::dvec3& seed, double direction) {
  std::vector<glm::dvec3> line{seed};
  glm::dvec3 p = seed;
  const double h = direction * kStep;
  for (int i = 0; i < kMaxSteps; ++i) {
    const glm::dvec3 k1 = abcVelocity(p), k2 = abcVelocity(p + 0.5 * h * k1);
    const glm::dvec3 k3 = abcVelocity(p + 0.5 * h * k2), k4 = abcVelocity(p + h * k3);
    p += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    if (!insideBox(p)) break;
    line.push_back(p);
  }
  return line;
}

std::shared_ptr<TriangleMesh> tubeMesh() {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  const double toWorld = 2.0 * kWorldHalfSize / kTwoPi;
  for (int i = 0; i < kSeedsPerSide; ++i)
    for (int j = 0; j < kSeedsPerSide; ++j) {
      const glm::dvec3 seed((i + 0.5) * kTwoPi / kSeedsPerSide, (j + 0.5) * kTwoPi / kSeedsPerSide, 0.5 * kTwoPi);
      std::vector<glm::dvec3> back = traceHalf(seed, -1.0), ahead = traceHalf(seed, 1.0);
      std::vector<glm::dvec3> line(back.rbegin(), back.rend());
      line.insert(line.end(), ahead.begin() + 1, ahead.end());  // the seed once
      if (line.size() < 2) continue;
      lines->InsertNextCell(static_cast<vtkIdType>(line.size()));
      for (const glm::dvec3& p : line) {
        const glm::dvec3 w = (p - glm::dvec3(0.5 * kTwoPi)) * toWorld;
        lines->InsertCellPoint(points->InsertNextPoint(w.x, w.y, w.z));
      }
    }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);
  vtkNew<vtkTubeFilter> tubes;
  tubes->SetInputData(poly);
  tubes->SetRadius(kTubeRadius);
  tubes->SetNumberOfSides(10);
  tubes->CappingOn();
  tubes->Update();
  return std::make_shared<TriangleMesh>(triangleMeshOf(*tubes->GetOutput()));
}

}  // namespace

Scene makeStreamlineScene() {
  Scene scene;
  addPlaced(*scene.root, tubeMesh(), glm::dmat4(1.0), glm::vec3(kDefaultAlbedo), "streamline tubes");
  scene.camera.position = {6.0, -8.5, 5.0};
  scene.camera.focalPoint = {0.0, 0.0, 0.0};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 30.0;
  scene.root->setAORadius(0.4);  // a tenth of the box: a few tube spacings
  return scene;
}

}  // namespace aokit
