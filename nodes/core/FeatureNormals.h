#pragma once
// Vertex normals that follow a mesh's edges, as vtkPolyDataNormals computes them: around each
// vertex, faces that meet across an edge at a dihedral angle of at most the feature angle share
// one normal (area weighted over them); where the angle is larger the vertex is split, each smooth
// group getting a copy of it with its own normal. A box's corner becomes three vertices with the
// three face normals, a sphere's vertices stay one each. A feature angle of 180 degrees splits
// nothing (TriangleMesh::computeNormals). Degenerate (zero-area) faces join their neighbours.
#include "core/TriangleMesh.h"

namespace aokit {

constexpr double kDefaultFeatureAngle = 30.0;  //!< degrees, VTK's default

// The mesh with split vertices and their normals; positions of copies equal their originals and
// triangles keep their order. featureAngleDegrees in [0, 180] (std::invalid_argument otherwise).
TriangleMesh withFeatureNormals(const TriangleMesh& mesh, double featureAngleDegrees = kDefaultFeatureAngle);

}  // namespace aokit
