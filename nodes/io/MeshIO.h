#pragma once
// Loading triangle meshes from files: OFF, OBJ and PLY through OpenMesh (VTK's reader as a
// fallback for OBJ; not for PLY, where vtkPLYReader crashes on corrupt files), STL by aokit itself
// (io/StlFormat.h), VTP, VTU and legacy VTK through VTK.
#include <string>
#include <vector>

#include "core/FeatureNormals.h"
#include "core/TriangleMesh.h"

namespace aokit {

// Reads the mesh at `path`, chosen by extension (case-insensitive): .off .obj .ply .stl .vtp .vtu
// .vtk. Polygons are fan-triangulated (exact for convex ones), non-manifold parts kept as they are
// (a triangle soup, as renderers want it). File normals are kept only where the format stores
// them per vertex (PLY, NOFF, VTK point normals) and every vertex has a usable one; otherwise
// normals follow the mesh's edges: vertices are split where faces meet at more than
// `featureAngle` degrees (core/FeatureNormals.h; 180 smooths across every edge). The result
// passes TriangleMesh::validate().
//
// Every failure throws std::runtime_error with one line "<path>: <problem>", e.g.
// "x.off: face 3 refers to vertex 12, but the file has 8 vertices". Files are first checked here
// (declared counts, list lengths, index ranges, number syntax), since the library readers trust
// them; the readers then run in a child process (IsolatedRead.h) whose crashes, hangs and
// runaway allocations on corrupt files become errors too. Nothing is printed.
// Limits: files up to 1 GiB; OFF must be ASCII with each face on one line. README "Input
// validation" lists what each format's checks refuse and which leniencies they keep.
TriangleMesh loadMesh(const std::string& path, double featureAngle = kDefaultFeatureAngle);

// The extensions loadMesh accepts, with the dot, lower case.
std::vector<std::string> meshExtensions();

}  // namespace aokit
