#pragma once
// Bakes a grid field (seed 002) with Embree.
//
// The padded box is the occluder's bounding box grown by padding * R on every side (nothing
// beyond R occludes, so padding = 1 covers the whole region of influence). At each grid point,
// gridRays rays over the whole sphere (spherical Fibonacci, turned per point) measure k(d) within
// R; term d is (4 / M) * sum_j k_j max(w_j.d, 0), the ray estimate of the cosine-weighted half-sphere
// integral (1/pi) int V k (w.d) dw: the seed's half-cube average of an 8x8 cube-map capture, but
// weighted by the cosine, so a term is exactly the AO of a surface facing d (the brief's choice of
// "rays giving the same half-cube cosine-weighted averages"). Points inside the occluder see its
// back faces in every direction and get 1: the grid is a blurred voxelization of the occluder.
// Then the seed's 3x3x3 blur and the edge fade (GridField.h).
#include <functional>
#include <vector>

#include "fields/BakeMesh.h"
#include "fields/GridField.h"

namespace aokit {

// settings.kind must be grid6 or grid4 and settings.resolution resolved (> 0); radius > 0 in the
// mesh's units. progress may throw to cancel.
GridField bakeGridField(const BakeMesh& mesh, const FieldBakeSettings& settings, double radius, Falloff falloff,
                        const std::function<void(double)>& progress = {});

// The seed's 3x3x3 kernel on an n^3 grid of `channels` interleaved values: weight (z + 1)^2 for a
// tap with z zero offsets (1 4 1 / 4 9 4 / 1 4 1 around 4 9 4 / 9 16 9 / 4 9 4, sum 126), taps
// outside the grid left out and the rest renormalized.
void blurGrid(std::vector<float>& values, int n, int channels);

// Edge fade of grid index i (0..n-1): smoothstep(0, fadeCells, distance to the nearest face in
// cells); 0 on the outermost layer whatever fadeCells is.
double gridEdgeFade(int i, int n, double fadeCells);

}  // namespace aokit
