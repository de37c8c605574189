#pragma once
// Grid-field evaluation (seed 002) on the CPU: the specification a GLSL port mirrors.
//
// Transforms: F = occluder -> field space (GridField::fieldFromOccluder), O = occluder -> world,
// R = receiver -> world. For a receiver point p_r with normal n_r (receiver coordinates):
//   n_o = normalize(N(O^-1 R) n_r)          N(M) = inverse transpose of M's upper 3x3 (the seed
//                                           writes O^-1 R n_r: the same for rigid transforms)
//   p   = F O^-1 R p_r + n_o * bias / N     the normal offset, added in field space as the seed does
//   T   = trilinear(p)                      GL_LINEAR, GL_CLAMP_TO_EDGE (TextureSampling.h)
//   grid6: w = (max(-n_o, 0), max(n_o, 0)), A = dot(T_neg, w.neg) + dot(T_pos, w.pos)
//   grid4: w = max(Nt n_o, 0),               A = dot(T, w)      Nt: rows = tetrahedronDirections()
//   weights = normalized: A /= sum(w)        (seed: no division)
//   A = clamp(A, 0, 1)
// The seed's weights are exact for a small occluder (terms proportional to max(u.d, 0), and
// sum_d max(n.d, 0) max(u.d, 0) = n.u when n and u share signs) but overshoot near large ones,
// up to sum(w) = |n|_1 <= sqrt 3 for grid6. Normalized weights are exact for uniform occlusion and
// for normals along a term direction. Against the Embree reference, at random points and normals
// within R of the sphere of sphere-plane (grid6, N = 32, bias 1): RMSE 0.115 with the seed's
// weights, 0.039 normalized; hence the default.
#include <glm/glm.hpp>

#include "fields/FieldEvalSettings.h"
#include "fields/GridField.h"

namespace aokit {

// p, n: receiver point and unit normal in occluder coordinates.
double evaluateGridField(const GridField& field, const glm::dvec3& p, const glm::dvec3& n,
                         const FieldEvalSettings& options = {});

// The same with the seed's transforms: pr, nr in receiver coordinates.
double evaluateGridField(const GridField& field, const glm::dmat4& occluderToWorld, const glm::dmat4& receiverToWorld,
                         const glm::dvec3& pr, const glm::dvec3& nr, const FieldEvalSettings& options = {});

}  // namespace aokit
