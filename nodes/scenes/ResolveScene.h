#pragma once
// A scene named the way every front end names one (the CLI, `aokit view`, Python): a built-in
// scene's name, a .json scene file, or a mesh file (.off .obj .ply .stl .vtp .vtu .vtk) shown
// alone, with the camera and R (a tenth of its diagonal) from its bounds.
#include <string>

#include "core/FeatureNormals.h"
#include "core/Scene.h"

namespace aokit {

// Throws std::invalid_argument (one line) naming the built-ins when `spec` is none of the three;
// a mesh without normals gets normals split at featureAngle degrees.
Scene resolveScene(const std::string& spec, double featureAngle = kDefaultFeatureAngle);
// Whether the name ends in one of the mesh extensions above (any case).
bool isMeshFile(const std::string& spec);

}  // namespace aokit
