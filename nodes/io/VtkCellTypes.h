#pragma once
// VTK's cell types as the dataset prechecks need them: which codes exist and how many points each
// takes. A cell whose point count does not fit its type sends VTK's geometry filter reading past
// its arrays.
#include <cstdint>
#include <string>

namespace aokit {

// Checks one unstructured-grid cell: a known type code, a point count that fits it, point ids in
// [0, points). `faceStream`: a polyhedron's ids are legacy VTK's face stream (face count, then
// each face's point count and ids) rather than its points. Returns the problem, or "" if none.
std::string checkCell(int type, const long long* ids, std::uint64_t n, long long points, bool faceStream);

}  // namespace aokit
