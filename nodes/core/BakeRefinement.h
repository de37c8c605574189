#pragma once
// Points added where baked per-point values change faster than the mesh's vertices can follow. A
// value baked per point is drawn interpolated across each triangle, so where it steps steeply from
// one point to the next (two streamline tubes touching between their ring vertices) the triangle
// shows a ramp the surface does not have. One refinement halves every edge whose ends differ by
// more than `step` (on any side's values) and that is longer than `minLength`; triangles with one,
// two or three halved edges become two, three or four, so the result stays conforming. The decision
// is per edge of the surface (copies at a crease halve together: no cracks), and it reads only the
// values, so a loader with the values rebuilds the same points.
#include <cstddef>
#include <functional>

#include "core/CreaseSplit.h"
#include "core/TriangleMesh.h"

namespace aokit {

// value(side, point): the baked value of `point` (0 <= side < sides).
using PointValue = std::function<float(int side, std::uint32_t point)>;

// Adds midpoints after split's points (their normals: their ends' normals averaged) and returns how
// many; 0 leaves the split as it was.
std::size_t refineWhereValuesStep(CreaseSplit& split, const TriangleMesh& mesh, const PointValue& value, int sides,
                                  float step, double minLength);

}  // namespace aokit
