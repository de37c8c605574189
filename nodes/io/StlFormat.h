#pragma once
// STL, ASCII and binary, read by aokit itself. STL is too simple to need a library and both
// library readers invent geometry from bad files: OpenMesh's ASCII reader takes any line that
// contains "outer" (a solid named "outer_wall") for the start of a loop and reads exactly three
// vertex lines whatever they hold, and both of its readers merge a NaN vertex with whatever the
// comparison happens to match, then drop the "degenerate" triangle without a word.
#include <string_view>

#include "core/TriangleMesh.h"

namespace aokit {

// Parses a whole STL file. ASCII when it starts with "solid" and parses as ASCII; binary when its
// size is exactly 84 + 50 x (the count at byte 80). Vertices with identical coordinates are
// shared; triangles with two identical vertices are dropped, as every STL reader does. Throws
// std::runtime_error with one line naming the line (ASCII) or triangle (binary) at fault.
// Positions only: STL normals are per facet, so loadMesh computes vertex normals.
TriangleMesh parseStl(std::string_view data);

}  // namespace aokit
