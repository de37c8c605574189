#pragma once
// A vtkPolyData's surface as the kit's TriangleMesh, triangulated as VTK's OpenGL mappers draw it:
// polygons as fans from their first point, triangle strips with alternating winding; vertices and
// lines have no surface and are left out. Point normals come along when the data has three-
// component ones for every point; otherwise they are computed. The mesh is not validated (a
// non-finite point is the bake's error to name).
#include "core/TriangleMesh.h"

class vtkPolyData;

namespace aokit {

TriangleMesh triangleMeshOf(vtkPolyData& poly);

}  // namespace aokit
