// render/PolyDataMesh: a polydata's surface triangulated as VTK's mappers draw it; and the field
// occluders' own-pixel rule for occluders that share an instance id (FieldSceneEval's ownPixel).
#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "fields/FieldSceneEval.h"
#include "render/PolyDataMesh.h"

using namespace aokit;

TEST(PolyDataMesh, QuadsBecomeFansStripsAlternateLinesAndVerticesDrop) {
  vtkNew<vtkPoints> points;
  for (int i = 0; i < 6; ++i) points->InsertNextPoint(i % 3, i / 3, 0.0);  // two rows of three
  vtkNew<vtkCellArray> polys, strips, lines, verts;
  const vtkIdType quad[4] = {0, 1, 4, 3};
  polys->InsertNextCell(4, quad);
  const vtkIdType strip[4] = {4, 1, 5, 2};
  strips->InsertNextCell(4, strip);
  const vtkIdType line[2] = {0, 5};
  lines->InsertNextCell(2, line);
  const vtkIdType vert[1] = {2};
  verts->InsertNextCell(1, vert);
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->SetStrips(strips);
  poly->SetLines(lines);
  poly->SetVerts(verts);
  const TriangleMesh m = triangleMeshOf(*poly);
  ASSERT_EQ(m.triangles.size(), 4u);
  EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 4));
  EXPECT_EQ(m.triangles[1], glm::uvec3(0, 4, 3));
  EXPECT_EQ(m.triangles[2], glm::uvec3(4, 1, 5));
  EXPECT_EQ(m.triangles[3], glm::uvec3(5, 1, 2));  // odd strip triangle: its first two swapped, winding kept
  ASSERT_EQ(m.normals.size(), 6u);  // computed: the plane's +z (all four triangles wind the same way)
  for (const glm::vec3& n : m.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
  EXPECT_NO_THROW(m.validate());
}

TEST(PolyDataMesh, APlaneSourceKeepsItsNormalsAndNoSurfaceIsEmpty) {
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(4, 3);
  plane->Update();
  const TriangleMesh m = triangleMeshOf(*plane->GetOutput());
  EXPECT_EQ(m.triangles.size(), 24u);
  EXPECT_EQ(m.positions.size(), 20u);
  EXPECT_EQ(m.normals.size(), 20u);
  vtkNew<vtkPolyData> none;
  EXPECT_TRUE(triangleMeshOf(*none).empty());
}

TEST(FieldOwnPixel, AnIdSharedByOccludersIsOwnOnlyInsideEachBox) {
  FieldOccluder whole{0, glm::dmat4(1.0), 7, {}};
  EXPECT_TRUE(ownPixel(whole, 7, glm::dvec3(100.0)));
  EXPECT_FALSE(ownPixel(whole, 8, glm::dvec3(0.0)));
  FieldOccluder none{0, glm::dmat4(1.0), 0, {}};
  EXPECT_FALSE(ownPixel(none, 0, glm::dvec3(0.0)));
  FieldOccluder leaf{0, glm::dmat4(1.0), 7, {glm::dvec3(-1.0), glm::dvec3(1.0)}};
  EXPECT_TRUE(ownPixel(leaf, 7, glm::dvec3(0.5, -1.0, 1.0)));
  EXPECT_FALSE(ownPixel(leaf, 7, glm::dvec3(0.0, 0.0, -1.01)));  // a sibling leaf's pixel
  EXPECT_FALSE(ownPixel(leaf, 6, glm::dvec3(0.0)));
}
