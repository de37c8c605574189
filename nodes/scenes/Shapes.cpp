#include "scenes/Shapes.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/gtc/constants.hpp>

namespace aokit {
namespace {

void requirePositive(double v, const char* what) {
  if (!(v > 0.0) || !std::isfinite(v))
    throw std::invalid_argument(std::string(what) + " must be positive and finite");
}

void requireAtLeast(int v, int min, const char* what) {
  if (v < min) throw std::invalid_argument(std::string(what) + " must be at least " + std::to_string(min));
}

unsigned addVertex(TriangleMesh& m, const glm::dvec3& p, const glm::dvec3& n) {
  m.positions.emplace_back(p);
  m.normals.emplace_back(n);
  return static_cast<unsigned>(m.positions.size() - 1);
}

// Quad a-b-c-d, counter-clockwise seen from the side its normal points to.
void addQuad(TriangleMesh& m, unsigned a, unsigned b, unsigned c, unsigned d) {
  m.triangles.emplace_back(a, b, c);
  m.triangles.emplace_back(a, c, d);
}

}  // namespace

std::shared_ptr<TriangleMesh> makeUVSphere(double radius, int slices, int stacks) {
  requirePositive(radius, "sphere radius");
  requireAtLeast(slices, 3, "sphere slices");
  requireAtLeast(stacks, 2, "sphere stacks");
  auto m = std::make_shared<TriangleMesh>();
  // (stacks + 1) rings of (slices + 1) vertices: the seam and the poles are duplicated so that
  // every row is a plain grid row; no triangle is degenerate because the pole rows emit one each.
  for (int j = 0; j <= stacks; ++j) {
    const double theta = glm::pi<double>() * j / stacks;  // 0 at the south pole
    for (int i = 0; i <= slices; ++i) {
      const double phi = glm::two_pi<double>() * (i % slices) / slices;
      const glm::dvec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), -std::cos(theta));
      addVertex(*m, radius * n, n);
    }
  }
  const auto row = static_cast<unsigned>(slices + 1);
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const unsigned a = j * row + i, b = a + 1, c = a + row + 1, d = a + row;
      if (j > 0) m->triangles.emplace_back(a, b, c);
      if (j < stacks - 1) m->triangles.emplace_back(a, c, d);
    }
  }
  return m;
}

std::shared_ptr<TriangleMesh> makeBox(const glm::dvec3& size) {
  requirePositive(size.x, "box size x");
  requirePositive(size.y, "box size y");
  requirePositive(size.z, "box size z");
  auto m = std::make_shared<TriangleMesh>();
  const glm::dvec3 h = 0.5 * size;
  // Each face: its normal axis and two tangents u, v with u x v = n, so (-u-v, u-v, u+v, -u+v) is
  // counter-clockwise seen from outside.
  for (int axis = 0; axis < 3; ++axis) {
    for (double sign : {-1.0, 1.0}) {
      glm::dvec3 n(0.0), u(0.0), v(0.0);
      n[axis] = sign;
      u[(axis + 1) % 3] = 1.0;
      v[(axis + 2) % 3] = sign;  // flips with the normal to keep u x v = n
      const glm::dvec3 c = n * h, du = u * h, dv = v * h;
      const unsigned a = addVertex(*m, c - du - dv, n);
      addVertex(*m, c + du - dv, n);
      addVertex(*m, c + du + dv, n);
      addVertex(*m, c - du + dv, n);
      addQuad(*m, a, a + 1, a + 2, a + 3);
    }
  }
  return m;
}

std::shared_ptr<TriangleMesh> makeCylinder(double radius, double height, int segments) {
  requirePositive(radius, "cylinder radius");
  requirePositive(height, "cylinder height");
  requireAtLeast(segments, 3, "cylinder segments");
  auto m = std::make_shared<TriangleMesh>();
  auto ring = [&](int i) {
    const double phi = glm::two_pi<double>() * (i % segments) / segments;
    return glm::dvec3(std::cos(phi), std::sin(phi), 0.0);
  };
  // Side: pairs of bottom/top vertices sharing the radial normal.
  for (int i = 0; i <= segments; ++i) {
    const glm::dvec3 r = ring(i);
    addVertex(*m, radius * r, r);
    addVertex(*m, radius * r + glm::dvec3(0, 0, height), r);
  }
  for (unsigned i = 0; i < static_cast<unsigned>(segments); ++i)
    addQuad(*m, 2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1);
  // Caps: a centre vertex and their own ring, so their normals stay flat.
  for (double z : {0.0, height}) {
    const glm::dvec3 n(0, 0, z > 0.0 ? 1.0 : -1.0);
    const unsigned centre = addVertex(*m, glm::dvec3(0, 0, z), n);
    for (int i = 0; i < segments; ++i) addVertex(*m, radius * ring(i) + glm::dvec3(0, 0, z), n);
    for (unsigned i = 0; i < static_cast<unsigned>(segments); ++i) {
      const unsigned a = centre + 1 + i, b = centre + 1 + (i + 1) % segments;
      if (z > 0.0)
        m->triangles.emplace_back(centre, a, b);
      else
        m->triangles.emplace_back(centre, b, a);
    }
  }
  return m;
}

std::shared_ptr<TriangleMesh> makeGridPlane(double sizeX, double sizeY, int nx, int ny) {
  requirePositive(sizeX, "plane size x");
  requirePositive(sizeY, "plane size y");
  requireAtLeast(nx, 1, "plane cells x");
  requireAtLeast(ny, 1, "plane cells y");
  auto m = std::make_shared<TriangleMesh>();
  const glm::dvec3 n(0, 0, 1);
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      addVertex(*m, glm::dvec3(sizeX * (double(i) / nx - 0.5), sizeY * (double(j) / ny - 0.5), 0.0), n);
  const auto row = static_cast<unsigned>(nx + 1);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const unsigned a = j * row + i;
      addQuad(*m, a, a + 1, a + row + 1, a + row);
    }
  return m;
}

}  // namespace aokit
