#pragma once
// Cube-map faces and coordinates, in OpenGL's convention, and the bordered texel layout of the
// radial fields.
//
// Faces in GL order: 0 +X, 1 -X, 2 +Y, 3 -Y, 4 +Z, 5 -Z. A direction's face is its major axis; its
// face coordinates are (u, v) = (sc, tc) / |ma| in [-1, 1] with (sc, tc) from the GL spec's table
// (+X: -z, -y; -X: +z, -y; +Y: +x, +z; -Y: +x, -z; +Z: +x, -y; -Z: -x, -y), and the GL texture
// coordinates of that face are s = (u + 1) / 2, t = (v + 1) / 2.
//
// Bordered layout: each face is a (N + 2) x (N + 2) layer; texel (i, j), i, j in 0..N+1, sits at
// u = (2 i - 1) / N - 1 (likewise v with j). Interior texels (1..N) cover the face as an N x N
// cube map would; the border ring lies half a texel beyond the face edge, in the direction of the
// neighbouring face, so that bilinear filtering never leaves the layer: a direction with face
// coordinates (u, v) is sampled at GL texture coordinate ((u + 1) / 2 * N + 1) / (N + 2), i.e. at
// filter coordinate x = (u + 1) / 2 * N + 0.5 (texel i centred at x = i, TextureSampling.h),
// always in [0.5, N + 0.5]: texels 0..N+1 only.
#include <glm/glm.hpp>

namespace aokit {

// Direction (not normalized; its major-axis component is +-1) of face coordinates (u, v).
glm::dvec3 faceDirection(int face, double u, double v);

struct FaceCoordinates {
  int face = 0;
  double u = 0.0, v = 0.0;
};
// The face a direction falls on (ties go to x, then y, then z) and its face coordinates. A zero
// direction maps to +Z's centre.
FaceCoordinates directionToFace(const glm::dvec3& d);

// Face coordinate of bordered texel index i (0..N+1), and the filter coordinate of u.
inline double borderedTexelCentre(int i, int n) { return (2.0 * i - 1.0) / n - 1.0; }
inline double borderedFilterCoordinate(double u, int n) { return 0.5 * (u + 1.0) * n + 0.5; }

}  // namespace aokit
