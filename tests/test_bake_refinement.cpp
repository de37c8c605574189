// The refinement of a bake's points where the values step (core/BakeRefinement.h): only edges whose
// ends differ by more than the step and are longer than the shortest edge are halved; the refined
// triangles tile their mesh triangles exactly (same area, same facing), the surface stays closed
// (every edge met once in each direction: no cracks, no T-junctions), and copies of a crease edge
// on both sides are halved together at the same point.
#include <cmath>
#include <map>
#include <tuple>

#include <gtest/gtest.h>

#include "core/BakeRefinement.h"
#include "core/CreaseSplit.h"
#include "scenes/Shapes.h"

using namespace aokit;

namespace {

using Key = std::tuple<float, float, float>;
Key keyOf(const glm::vec3& p) { return {p.x, p.y, p.z}; }

// Every directed edge of the refined triangles, by its ends' exact positions, has its reverse once.
void expectClosed(const TriangleMesh& mesh, const CreaseSplit& s) {
  std::map<std::pair<Key, Key>, int> directed;
  for (const glm::uvec3& t : s.triangles)
    for (int k = 0; k < 3; ++k)
      ++directed[{keyOf(s.position(mesh, t[k])), keyOf(s.position(mesh, t[(k + 1) % 3]))}];
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "an edge drawn twice the same way";
    const auto reverse = directed.find({edge.second, edge.first});
    ASSERT_NE(reverse, directed.end()) << "an edge without its neighbour: a crack or a T-junction at (" << std::get<0>(edge.first) << ", " << std::get<1>(edge.first) << ", " << std::get<2>(edge.first) << ") - (" << std::get<0>(edge.second) << ", " << std::get<1>(edge.second) << ", " << std::get<2>(edge.second) << ")";
    EXPECT_EQ(reverse->second, 1);
  }
}

glm::vec3 areaVector(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) { return 0.5f * glm::cross(b - a, c - a); }

// The refined triangles of each mesh triangle add up to it and face its way.
void expectTiles(const TriangleMesh& mesh, const CreaseSplit& s) {
  ASSERT_EQ(s.parent.size(), s.triangles.size());
  std::vector<glm::vec3> sum(mesh.triangles.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i < s.triangles.size(); ++i) {
    ASSERT_LT(s.parent[i], mesh.triangles.size());
    if (i > 0) EXPECT_LE(s.parent[i - 1], s.parent[i]) << "in the mesh's order";
    const glm::uvec3& t = s.triangles[i];
    const glm::uvec3& m = mesh.triangles[s.parent[i]];
    const glm::vec3 a = areaVector(s.position(mesh, t.x), s.position(mesh, t.y), s.position(mesh, t.z));
    const glm::vec3 whole = areaVector(mesh.positions[m.x], mesh.positions[m.y], mesh.positions[m.z]);
    EXPECT_GT(glm::dot(a, whole), 0.0f) << "triangle " << i << " turned over";
    sum[s.parent[i]] += a;
  }
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const glm::uvec3& m = mesh.triangles[f];
    const glm::vec3 whole = areaVector(mesh.positions[m.x], mesh.positions[m.y], mesh.positions[m.z]);
    EXPECT_LT(glm::length(sum[f] - whole), 1e-5f * glm::length(whole) + 1e-9f) << "mesh triangle " << f;
  }
}

// A UV sphere closed exactly: its pole vertices, one a slice, snapped to one position.
TriangleMesh closedSphere() {
  TriangleMesh sphere = *makeUVSphere(1.0, 24, 12);
  for (glm::vec3& p : sphere.positions) p = glm::round(p * 1e5f) / 1e5f;
  return sphere;
}

}  // namespace

TEST(BakeRefinement, HalvesOnlyEdgesWhoseValuesStepAndStaysClosed) {
  const TriangleMesh sphere = closedSphere();
  CreaseSplit unrefined = splitAtCreases(sphere);
  expectClosed(sphere, [&] {
    CreaseSplit all = unrefined;
    all.triangles = sphere.triangles;
    return all;
  }());
  CreaseSplit s = unrefined;
  ASSERT_FALSE(s.splits());
  // A step across the plane x = 0.3: a band of edges crosses it.
  const auto stepAt = [&](const CreaseSplit& split) {
    return [&split, &sphere](int, std::uint32_t p) { return split.position(sphere, p).x > 0.3f ? 1.0f : 0.0f; };
  };
  const std::size_t added = refineWhereValuesStep(s, sphere, stepAt(s), 1, 0.5f, 0.0);
  ASSERT_GT(added, 0u);
  EXPECT_EQ(s.pointCount(), sphere.positions.size() + added);
  EXPECT_TRUE(s.splits());
  ASSERT_EQ(s.normals.size(), s.pointCount());
  for (const SplitMidpoint& m : s.midpoints) {
    const glm::vec3 a = s.position(sphere, m.a), b = s.position(sphere, m.b);
    EXPECT_NE(a.x > 0.3f, b.x > 0.3f) << "an edge halved without a step";
    EXPECT_NEAR(m.weights.x + m.weights.y + m.weights.z, 1.0f, 1e-6f);
  }
  for (std::size_t k = 0; k < s.midpoints.size(); ++k) {
    const SplitMidpoint& m = s.midpoints[k];
    const glm::vec3 mid = s.position(sphere, s.vertexCount + k);
    EXPECT_LT(glm::length(mid - 0.5f * (s.position(sphere, m.a) + s.position(sphere, m.b))), 1e-6f);
  }
  expectClosed(sphere, s);
  expectTiles(sphere, s);
  // A second round halves the new edges that still cross the step, and stays closed.
  const std::size_t first = s.pointCount();
  EXPECT_GT(refineWhereValuesStep(s, sphere, stepAt(s), 1, 0.5f, 0.0), 0u);
  EXPECT_GT(s.pointCount(), first);
  expectClosed(sphere, s);
  expectTiles(sphere, s);
}

TEST(BakeRefinement, NothingStepsOrEveryEdgeIsShortAlready) {
  const TriangleMesh sphere = *makeUVSphere(1.0, 24, 12);
  CreaseSplit flat = splitAtCreases(sphere);
  EXPECT_EQ(refineWhereValuesStep(flat, sphere, [](int, std::uint32_t) { return 0.4f; }, 1, 0.01f, 0.0), 0u);
  EXPECT_FALSE(flat.splits());
  EXPECT_TRUE(flat.triangles.empty());
  EXPECT_TRUE(flat.parent.empty());
  CreaseSplit shortEdges = splitAtCreases(sphere);
  const auto alternate = [](int, std::uint32_t p) { return static_cast<float>(p % 2); };
  EXPECT_EQ(refineWhereValuesStep(shortEdges, sphere, alternate, 1, 0.5f, 10.0), 0u);
  EXPECT_FALSE(shortEdges.splits());
  // The back side's values count too.
  CreaseSplit back = splitAtCreases(sphere);
  const auto backSteps = [](int side, std::uint32_t p) { return side == 1 ? static_cast<float>(p % 2) : 0.0f; };
  EXPECT_GT(refineWhereValuesStep(back, sphere, backSteps, 2, 0.5f, 0.0), 0u);
}

TEST(BakeRefinement, CopiesAtACreaseAreHalvedTogether) {
  const TriangleMesh tube = *makeCylinder(0.2, 2.0, 10);
  CreaseSplit s = splitAtCreases(tube);
  ASSERT_TRUE(s.splits());
  const std::size_t copies = s.origin.size();
  // A value on one side of a crease only: the copies on the other side hold 0 along the same edge,
  // yet the edge is halved on both sides.
  const std::uint32_t stepping = s.triangles[0].x;
  const auto value = [&](int, std::uint32_t p) { return p == stepping ? 1.0f : 0.0f; };
  ASSERT_GT(refineWhereValuesStep(s, tube, value, 1, 0.5f, 0.0), 0u);
  EXPECT_EQ(s.origin.size(), copies);
  std::map<Key, int> atPosition;
  for (std::size_t k = 0; k < s.midpoints.size(); ++k) ++atPosition[keyOf(s.position(tube, s.vertexCount + copies + k))];
  // Each halved surface edge: one midpoint per side that has the edge (two at a crease, one on the
  // seam or a cap's rim whose vertices are their own), at one position.
  int shared = 0;
  for (const auto& [at, count] : atPosition) {
    EXPECT_LE(count, 2);
    shared += count == 2;
  }
  EXPECT_GT(shared, 0);
  expectTiles(tube, s);
}
