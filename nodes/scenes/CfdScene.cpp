// "cfd": the wall surfaces of a multiblock CFD case, one mesh per block as a flow solver writes them
// (a vtkMultiBlockDataSet shown through a composite mapper): a fuselage, a wing through it, two
// nacelles under the wing with narrow gaps, over a ground wall with a bump (ground effect). Block
// surfaces are fine structured grids (284,800 triangles in all) whose normals are computed with a
// 30-degree feature angle, as ParaView's Extract Surface + Generate Surface Normals gives them.
#include <cmath>
#include <functional>

#include "core/FeatureNormals.h"
#include "scenes/SceneBuilders.h"
#include "scenes/SceneBuilding.h"

namespace aokit {
namespace {

constexpr double kPi = 3.141592653589793;
using Surface = std::function<glm::dvec3(double u, double v)>;  // (u, v) in [0, 1]^2

// An nu x nv grid of quads over (u, v), two triangles each, wound so that du x dv is the normal.
TriangleMesh gridSurface(int nu, int nv, const Surface& at) {
  TriangleMesh m;
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) m.positions.emplace_back(at(double(i) / nu, double(j) / nv));
  auto id = [nu](int i, int j) { return unsigned(j * (nu + 1) + i); };
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      m.triangles.emplace_back(id(i, j), id(i + 1, j), id(i + 1, j + 1));
      m.triangles.emplace_back(id(i, j), id(i + 1, j + 1), id(i, j + 1));
    }
  return m;
}

// Turns a closed body's triangles outward: the area-weighted facet normals must point away from
// its centroid on the whole. Then feature-angle normals.
std::shared_ptr<TriangleMesh> closedBody(TriangleMesh m) {
  glm::dvec3 centroid(0.0);
  for (const auto& p : m.positions) centroid += glm::dvec3(p);
  centroid /= double(m.positions.size());
  double outward = 0.0;
  for (const auto& t : m.triangles) {
    const glm::dvec3 a(m.positions[t.x]), b(m.positions[t.y]), c(m.positions[t.z]);
    outward += glm::dot(glm::cross(b - a, c - a), (a + b + c) / 3.0 - centroid);
  }
  if (outward < 0.0)
    for (auto& t : m.triangles) std::swap(t.y, t.z);
  return std::make_shared<TriangleMesh>(withFeatureNormals(m));
}

// A body of revolution along +x from x0, `length` long, blunt nose, pointed tail.
std::shared_ptr<TriangleMesh> bodyOfRevolution(double x0, double length, double radius, const glm::dvec3& axisAt,
                                               int nu, int nv) {
  return closedBody(gridSurface(nu, nv, [=](double u, double v) {
    // Elliptic nose over the first fifth, a cylinder, a tail closing to a point over the last 30 %.
    const double profile = u < 0.2   ? std::sqrt(std::max(0.0, 1.0 - (1.0 - u / 0.2) * (1.0 - u / 0.2)))
                           : u < 0.7 ? 1.0
                                     : 1.0 - ((u - 0.7) / 0.3) * ((u - 0.7) / 0.3);
    const double r = radius * profile;
    return axisAt + glm::dvec3(x0 + length * u, r * std::cos(2 * kPi * v), r * std::sin(2 * kPi * v));
  }));
}

// NACA 0012 half thickness at chord fraction x in [0, 1] (closed trailing edge).
double naca0012(double x) {
  return 0.6 * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1036 * x * x * x * x);
}

// A wing along y, span 2 * halfSpan, elliptic chord and thickness that close it at the tips.
std::shared_ptr<TriangleMesh> wing(double rootChord, double halfSpan, const glm::dvec3& rootLeadingEdge, int nu,
                                   int nv) {
  return closedBody(gridSurface(nu, nv, [=](double u, double v) {
    const double y = halfSpan * (2.0 * v - 1.0);
    const double taper = std::sqrt(std::max(0.0, 1.0 - (y / halfSpan) * (y / halfSpan)));
    const double chord = rootChord * (0.3 + 0.7 * taper);
    const double x = 0.5 * (1.0 + std::cos(2 * kPi * u));  // trailing edge, upper side, leading edge, lower side
    const double side = u < 0.5 ? 1.0 : -1.0;
    const double sweep = 0.3 * std::abs(y);
    return rootLeadingEdge + glm::dvec3(sweep + chord * x, y, side * chord * naca0012(x) * taper + 0.05 * std::abs(y));
  }));
}

// The ground wall: z = bump(x, y), +z up.
std::shared_ptr<TriangleMesh> groundWall(double sizeX, double sizeY, int nx, int ny) {
  TriangleMesh m = gridSurface(nx, ny, [=](double u, double v) {
    const double x = sizeX * (u - 0.5), y = sizeY * (v - 0.5);
    return glm::dvec3(x, y, 0.15 * std::exp(-((x - 1.2) * (x - 1.2) + y * y) / 0.6));
  });
  return std::make_shared<TriangleMesh>(withFeatureNormals(m));
}

}  // namespace

Scene makeCfdScene() {
  Scene scene;
  const glm::vec3 grey(kDefaultAlbedo);
  Group& root = *scene.root;
  addPlaced(root, groundWall(8.0, 5.0, 400, 250), glm::dmat4(1.0), grey, "ground block");
  addPlaced(root, bodyOfRevolution(-1.5, 3.0, 0.3, {0.0, 0.0, 0.6}, 200, 100), glm::dmat4(1.0), grey,
            "fuselage block");
  addPlaced(root, wing(0.9, 1.3, {-0.4, 0.0, 0.42}, 200, 80), glm::dmat4(1.0), grey, "wing block");
  for (double side : {-1.0, 1.0})
    addPlaced(root, bodyOfRevolution(-0.45, 0.7, 0.1, {0.0, side * 0.75, 0.3}, 80, 40), glm::dmat4(1.0), grey,
              "nacelle block");
  scene.camera.position = {-3.4, -4.1, 2.4};
  scene.camera.focalPoint = {0.1, 0.0, 0.45};
  scene.camera.viewUp = {0.0, 0.0, 1.0};
  scene.camera.viewAngleDeg = 30.0;
  scene.root->setAORadius(0.5);  // about the fuselage's diameter and the gaps under it
  return scene;
}

}  // namespace aokit
