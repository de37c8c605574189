#include "render/PolyDataMesh.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace aokit {

TriangleMesh triangleMeshOf(vtkPolyData& poly) {
  TriangleMesh out;
  vtkPoints* points = poly.GetPoints();
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  if (n == 0) return out;
  out.positions.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i) {
    double p[3];
    points->GetPoint(i, p);
    out.positions[static_cast<std::size_t>(i)] = glm::vec3(p[0], p[1], p[2]);
  }
  auto index = [](vtkIdType i) { return static_cast<unsigned>(i); };
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  vtkCellArray* polys = poly.GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
    for (vtkIdType k = 2; k < count; ++k) out.triangles.emplace_back(index(ids[0]), index(ids[k - 1]), index(ids[k]));
  vtkCellArray* strips = poly.GetStrips();
  for (strips->InitTraversal(); strips->GetNextCell(count, ids);)
    for (vtkIdType k = 2; k < count; ++k) {
      if (k % 2 == 0) out.triangles.emplace_back(index(ids[k - 2]), index(ids[k - 1]), index(ids[k]));
      else out.triangles.emplace_back(index(ids[k - 1]), index(ids[k - 2]), index(ids[k]));
    }
  vtkDataArray* normals = poly.GetPointData()->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3 && normals->GetNumberOfTuples() == n) {
    out.normals.resize(out.positions.size());
    for (vtkIdType i = 0; i < n; ++i) {
      double v[3];
      normals->GetTuple(i, v);
      out.normals[static_cast<std::size_t>(i)] = glm::vec3(v[0], v[1], v[2]);
    }
  } else if (!out.triangles.empty()) {
    out.computeNormals();
  }
  return out;
}

}  // namespace aokit
