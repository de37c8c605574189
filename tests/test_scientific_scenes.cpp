// The scientific built-in scenes (isosurface, streamlines, cfd): the sizes such data comes in,
// normals that agree with the facets' winding, the isosurface open at its domain's faces only, the
// CFD blocks closed and facing out.
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

#include <gtest/gtest.h>

#include "core/Geometry.h"
#include "core/NodeVisitor.h"
#include "scenes/BuiltinScenes.h"

using namespace aokit;

namespace {

std::size_t triangleCount(Scene& s) {
  std::size_t n = 0;
  for (const auto& inst : collectInstances(*s.root)) n += inst.geometry->mesh()->triangles.size();
  return n;
}

glm::dvec3 facetNormal(const TriangleMesh& m, const glm::uvec3& t) {
  const glm::dvec3 a(m.positions[t.x]), b(m.positions[t.y]), c(m.positions[t.z]);
  return glm::cross(b - a, c - a);
}

// Fraction of non-degenerate triangles whose three vertex normals lie on the winding's side.
double windingAgreement(const TriangleMesh& m) {
  std::size_t agree = 0, counted = 0;
  for (const auto& t : m.triangles) {
    const glm::dvec3 n = facetNormal(m, t);
    if (glm::length(n) < 1e-12) continue;
    ++counted;
    if (glm::dot(n, glm::dvec3(m.normals[t.x])) > 0 && glm::dot(n, glm::dvec3(m.normals[t.y])) > 0 &&
        glm::dot(n, glm::dvec3(m.normals[t.z])) > 0)
      ++agree;
  }
  return counted ? double(agree) / counted : 0.0;
}

// Edges used by exactly one triangle, keyed by their vertices' positions rounded to 1e-5 (split
// vertices, seams and a grid's collapsed rows share one); edges of zero length are left out.
std::vector<std::pair<glm::vec3, glm::vec3>> boundaryEdges(const TriangleMesh& m) {
  using Key = std::tuple<long, long, long>;
  auto key = [&](unsigned i) {
    const glm::vec3& p = m.positions[i];
    return Key(std::lround(p.x * 1e5), std::lround(p.y * 1e5), std::lround(p.z * 1e5));
  };
  std::map<std::pair<Key, Key>, std::pair<int, unsigned>> uses;  // count, and one vertex of the edge
  for (const auto& t : m.triangles)
    for (int e = 0; e < 3; ++e) {
      Key a = key(t[e]), b = key(t[(e + 1) % 3]);
      if (a == b) continue;
      if (b < a) std::swap(a, b);
      auto& u = uses[{a, b}];
      ++u.first;
      u.second = t[e];
    }
  std::vector<std::pair<glm::vec3, glm::vec3>> out;
  for (const auto& [edge, u] : uses)
    if (u.first == 1) {
      const auto& b = edge.second;
      out.emplace_back(m.positions[u.second], glm::vec3(std::get<0>(b), std::get<1>(b), std::get<2>(b)) * 1e-5f);
    }
  return out;
}

double signedVolume(const TriangleMesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles)
    v += glm::dot(glm::dvec3(m.positions[t.x]), glm::cross(glm::dvec3(m.positions[t.y]), glm::dvec3(m.positions[t.z]))) / 6.0;
  return v;
}

}  // namespace

TEST(ScientificScenes, SizesAsSuchDataComesIn) {
  for (const char* name : {"isosurface", "streamlines", "cfd"}) {
    SCOPED_TRACE(name);
    Scene s = makeBuiltinScene(name);
    const std::size_t n = triangleCount(s);
    EXPECT_GE(n, 100000u);
    EXPECT_LE(n, 1000000u);
  }
}

TEST(ScientificScenes, NormalsAgreeWithTheWinding) {
  for (const char* name : {"isosurface", "streamlines", "cfd"}) {
    SCOPED_TRACE(name);
    Scene s = makeBuiltinScene(name);
    for (const auto& inst : collectInstances(*s.root)) {
      SCOPED_TRACE(inst.geometry->name());
      EXPECT_GT(windingAgreement(*inst.geometry->mesh()), 0.995);
    }
  }
}

TEST(ScientificScenes, IsosurfaceIsOpenOnlyAtTheDomainFaces) {
  Scene s = makeBuiltinScene("isosurface");
  const auto inst = collectInstances(*s.root);
  ASSERT_EQ(inst.size(), 1u);  // both contours in one mesh, as one contour filter gives them
  const auto edges = boundaryEdges(*inst[0].geometry->mesh());
  ASSERT_GT(edges.size(), 100u);  // cut open by the domain
  auto onFace = [](const glm::vec3& p) {
    const float m = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return std::abs(m - 1.6f) < 1e-4f;
  };
  for (const auto& [a, b] : edges) ASSERT_TRUE(onFace(a) && onFace(b)) << a.x << "," << a.y << "," << a.z;
}

TEST(ScientificScenes, CfdBlocksAreClosedAndFaceOut) {
  Scene s = makeBuiltinScene("cfd");
  const auto inst = collectInstances(*s.root);
  ASSERT_EQ(inst.size(), 5u);  // ground, fuselage, wing, two nacelles
  for (std::size_t i = 1; i < inst.size(); ++i) {
    const TriangleMesh& m = *inst[i].geometry->mesh();
    SCOPED_TRACE(inst[i].geometry->name());
    EXPECT_GT(signedVolume(m), 0.0);
    EXPECT_TRUE(boundaryEdges(m).empty());
  }
  const TriangleMesh& ground = *inst[0].geometry->mesh();
  for (const auto& n : ground.normals) ASSERT_GT(n.z, 0.9f);
}
