// Feature-angle normals (core/FeatureNormals.h): a box whose corners are shared vertices gets the
// normal of each face at each of its corners (exact), a sphere is not split and keeps the smooth
// normals, 180 degrees splits nothing, and a mesh file without normals is loaded that way.
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include <gtest/gtest.h>

#include "core/FeatureNormals.h"
#include "io/MeshIO.h"
#include "scenes/Shapes.h"

using namespace aokit;
namespace fs = std::filesystem;

namespace {

// The unit cube [0,1]^3 with its eight corners shared by all twelve triangles (a plain OBJ/OFF
// cube); without its front face (y = 0) when open.
TriangleMesh sharedCornerBox(bool open) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) m.positions.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const unsigned quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (int q = 0; q < 6; ++q) {
    if (open && q == 2) continue;  // the face y = 0
    const unsigned* v = quads[q];
    m.triangles.emplace_back(v[0], v[1], v[2]);
    m.triangles.emplace_back(v[0], v[2], v[3]);
  }
  return m;
}

glm::vec3 faceNormal(const TriangleMesh& m, const glm::uvec3& t) {
  return glm::normalize(glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]));
}

}  // namespace

TEST(FeatureNormals, ABoxGetsEachFacesNormalAtEachOfItsCorners) {
  for (bool open : {false, true}) {
    const TriangleMesh box = sharedCornerBox(open);
    const TriangleMesh n = withFeatureNormals(box);
    EXPECT_EQ(n.positions.size(), open ? 20u : 24u) << "a corner per face that meets it";
    ASSERT_EQ(n.triangles.size(), box.triangles.size());
    for (std::size_t f = 0; f < n.triangles.size(); ++f) {
      const glm::uvec3 t = n.triangles[f];
      const glm::vec3 face = faceNormal(box, box.triangles[f]);
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(n.positions[t[k]], box.positions[box.triangles[f][k]]);
        EXPECT_GT(glm::dot(n.normals[t[k]], face), 0.99999f) << "triangle " << f;
      }
    }
    n.validate();
  }
}

TEST(FeatureNormals, ASphereIsNotSplitAndOneEightyDegreesSplitsNothing) {
  TriangleMesh sphere = *makeUVSphere(1.0, 48, 24);
  sphere.normals.clear();
  const TriangleMesh n = withFeatureNormals(sphere);
  TriangleMesh smooth = sphere;
  smooth.computeNormals();
  ASSERT_EQ(n.positions.size(), sphere.positions.size());
  for (std::size_t i = 0; i < n.normals.size(); ++i) EXPECT_GT(glm::dot(n.normals[i], smooth.normals[i]), 0.99999f);

  const TriangleMesh box = sharedCornerBox(false);
  const TriangleMesh all = withFeatureNormals(box, 180.0);
  TriangleMesh blob = box;
  blob.computeNormals();
  ASSERT_EQ(all.positions.size(), 8u);
  for (std::size_t i = 0; i < 8; ++i) EXPECT_GT(glm::dot(all.normals[i], blob.normals[i]), 0.99999f);
  EXPECT_EQ(all.triangles, box.triangles);
}

TEST(FeatureNormals, AnAngleOutsideZeroToOneEightyIsRefused) {
  const TriangleMesh box = sharedCornerBox(false);
  EXPECT_THROW(withFeatureNormals(box, -1.0), std::invalid_argument);
  EXPECT_THROW(withFeatureNormals(box, 181.0), std::invalid_argument);
  EXPECT_THROW(withFeatureNormals(box, std::nan("")), std::invalid_argument);
  EXPECT_THROW(loadMesh("x.off", 200.0), std::invalid_argument);
}

TEST(FeatureNormals, AMeshFileWithoutNormalsIsLoadedWithThem) {
  const fs::path p = fs::temp_directory_path() / ("aokit-feature-" + std::to_string(::getpid()) + ".off");
  {
    const TriangleMesh box = sharedCornerBox(true);
    std::ofstream out(p);
    out << "OFF\n" << box.positions.size() << " " << box.triangles.size() << " 0\n";
    for (const auto& v : box.positions) out << v.x << " " << v.y << " " << v.z << "\n";
    for (const auto& t : box.triangles) out << "3 " << t.x << " " << t.y << " " << t.z << "\n";
  }
  const TriangleMesh split = loadMesh(p.string());
  const TriangleMesh smooth = loadMesh(p.string(), 180.0);
  fs::remove(p);
  EXPECT_EQ(split.positions.size(), 20u);
  EXPECT_EQ(smooth.positions.size(), 8u);
  for (std::size_t f = 0; f < split.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k)
      EXPECT_GT(glm::dot(split.normals[split.triangles[f][k]], faceNormal(split, split.triangles[f])), 0.99999f);
}
