// The crease split (core/CreaseSplit.h) that the self-occlusion bake stores its values on: a
// ten-sided tube's shared ring vertices get one point per side with that side's facet normal (exact), a
// box whose corners are shared gets one point per face at each corner, and meshes without creases
// above the angle (a smooth sphere, a box that already carries split corners) get no copies and
// keep their own normals, so what is baked on them does not change.
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "core/CreaseSplit.h"
#include "scenes/Shapes.h"

using namespace aokit;

namespace {

glm::vec3 facetNormal(const TriangleMesh& m, const glm::uvec3& t) {
  return glm::normalize(glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]));
}

// The split's triangles name the same corners as the mesh's (a copy's origin is the vertex it
// replaces), and every point of a triangle carries that triangle's facet normal where it was split.
void expectConsistent(const TriangleMesh& mesh, const CreaseSplit& s) {
  ASSERT_EQ(s.normals.size(), s.pointCount());
  if (!s.splits()) {
    EXPECT_TRUE(s.triangles.empty());
    return;
  }
  ASSERT_EQ(s.triangles.size(), mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const unsigned p = s.triangles[f][k], v = mesh.triangles[f][k];
      ASSERT_LT(p, s.pointCount());
      EXPECT_EQ(p < s.vertexCount ? p : s.origin[p - s.vertexCount], v) << "triangle " << f;
    }
}

}  // namespace

TEST(CreaseSplit, ATenSidedTubeGetsOnePointPerSideWithItsFacetNormal) {
  const int sides = 10;
  const TriangleMesh tube = *makeCylinder(0.2, 2.0, sides);
  const CreaseSplit s = splitAtCreases(tube);
  expectConsistent(tube, s);
  // Ring vertices 1..sides-1 (bottom and top) are shared by two sides 36 degrees apart; the seam
  // (vertices 0 and sides) and the caps have their own vertices already.
  EXPECT_EQ(s.origin.size(), 2u * (sides - 1));
  // The seam's vertices belong to one side each: not split, they keep the mesh's normal.
  const auto seam = [&](unsigned v) { return v < 2 || v == 2u * sides || v == 2u * sides + 1; };
  const std::size_t sideTriangles = 2 * sides;
  for (std::size_t f = 0; f < sideTriangles; ++f) {
    const glm::vec3 facet = facetNormal(tube, tube.triangles[f]);
    for (int k = 0; k < 3; ++k) {
      const unsigned v = tube.triangles[f][k], p = s.triangles[f][k];
      if (seam(v))
        EXPECT_EQ(s.normals[p], tube.normals[v]);
      else
        EXPECT_GT(glm::dot(s.normals[p], facet), 0.99999f) << "triangle " << f;
    }
  }
  // The vertex normals lean 18 degrees off both sides; the split's are the sides' own.
  const glm::vec3 smooth = tube.normals[2];
  EXPECT_NEAR(glm::dot(smooth, facetNormal(tube, tube.triangles[0])), std::cos(glm::radians(18.0f)), 1e-4f);
}

TEST(CreaseSplit, ABoxWithSharedCornersGetsAPointPerFaceAtEachCorner) {
  TriangleMesh box;
  for (int i = 0; i < 8; ++i) box.positions.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const unsigned quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    box.triangles.emplace_back(q[0], q[1], q[2]);
    box.triangles.emplace_back(q[0], q[2], q[3]);
  }
  const CreaseSplit s = splitAtCreases(box);  // no normals: computed first
  expectConsistent(box, s);
  EXPECT_EQ(s.pointCount(), 24u);
  std::map<unsigned, std::set<unsigned>> pointsOfCorner;
  for (std::size_t f = 0; f < box.triangles.size(); ++f) {
    const glm::vec3 facet = facetNormal(box, box.triangles[f]);
    for (int k = 0; k < 3; ++k) {
      pointsOfCorner[box.triangles[f][k]].insert(s.triangles[f][k]);
      EXPECT_GT(glm::dot(s.normals[s.triangles[f][k]], facet), 0.99999f);
    }
  }
  for (const auto& [corner, points] : pointsOfCorner) EXPECT_EQ(points.size(), 3u) << "corner " << corner;
}

TEST(CreaseSplit, MeshesWithoutCreasesAboveTheAngleKeepTheirVerticesAndNormals) {
  const TriangleMesh sphere = *makeUVSphere(1.0, 48, 24);
  const TriangleMesh box = *makeBox(glm::dvec3(1.0, 2.0, 3.0));  // its corners are split already
  for (const TriangleMesh* mesh : {&sphere, &box}) {
    const CreaseSplit s = splitAtCreases(*mesh);
    EXPECT_FALSE(s.splits());
    EXPECT_EQ(s.pointCount(), mesh->positions.size());
    expectConsistent(*mesh, s);
    for (std::size_t i = 0; i < mesh->normals.size(); ++i) EXPECT_EQ(s.normals[i], mesh->normals[i]);
  }
  // Above the tube's 36 degrees the tube is smooth too.
  const TriangleMesh tube = *makeCylinder(0.2, 2.0, 10);
  EXPECT_FALSE(splitAtCreases(tube, 40.0).splits());
  EXPECT_THROW(splitAtCreases(tube, 200.0), std::invalid_argument);
}
