#pragma once
// The horizon limit of a cube field: what the cap model cannot know about where the occluder is.
// Not in the seeds; it corrects Algorithm 1 (and the cones of seed 001) where they fail most.
//
// Algorithm 1 sees an occluder as a cap (Omega, Upsilon) and counts the part of it above the
// receiver's horizon. An occluder beside the receiver whose points all lie at or below the tangent
// plane (a wheel's neighbour seen from the wheel's outer face) still has a cap straddling the
// horizon, so about half of it is counted where the true occlusion is 0. The occluder's bounding
// box in its own coordinates (field space) holds all of it, which bounds the elevation of every
// direction the occluder can block from receiver x with normal n:
//   s = max over the box of n.(y - x)       how far the box reaches above the tangent plane
//   d = distance from x to the box          (0 inside it)
//   sin(elevation) <= s / d                 (no bound where d <= s)
// The cap's occlusion is then scaled by the share of its cosine-weighted solid angle above the
// horizon that lies below that elevation: F(alpha, beta, theta_m), alpha the cap's half-angle,
// beta = acos(n.Upsilon), theta_m = asin(min(1, s / d)). F = 0 where s <= 0 (exact: nothing above
// the plane), 1 where the box reaches the cap's top. Exact for the box; a looser box only limits less.
//
// F as a table (R32F 3D texture, kSize^3, endpoint-inclusive, texels[(k * kSize + j) * kSize + i]):
//   x = alpha / pi, y = beta / pi, z = theta_m / (pi / 2); 1 where no part of the cap is above the
//   horizon. Built by quadrature over the polar angle (the cap's azimuthal width at each one).
#include <vector>

#include <glm/glm.hpp>

#include "core/TriangleMesh.h"
#include "fields/RadialField.h"

namespace aokit {

struct HorizonTable {
  static constexpr int kSize = 32;
  std::vector<float> texels;  // kSize^3
  // F for a cap of solid angle `solidAngle` whose axis makes cos = cosBeta with the normal, below
  // elevation thetaMax (radians, [0, pi / 2]); trilinear as the shader samples it.
  double sample(double solidAngle, double cosBeta, double thetaMax) const;
};

// Built at first use (thread-safe).
const HorizonTable& horizonTable();

// F by quadrature (the table's source; tests compare the two).
double horizonFraction(double halfAngle, double beta, double thetaMax, int steps = 2048);

// Sets field.hullBoxCentre and hullBoxHalf: the bounding box of the mesh the field was baked from
// (its own coordinates minus field.centre). Field files do not store it: a field read without its
// mesh keeps half < 0, no limit (FieldTechnique sets it from the occluder's mesh).
void updateHullBox(RadialField& field, const TriangleMesh& mesh);

// The factor in [0, 1] Algorithm 1's A is multiplied by. x, n: receiver position and unit normal
// in field space; solidAngle and cosBeta = n.Upsilon as the evaluator found them.
double horizonLimit(const RadialField& field, const glm::dvec3& x, const glm::dvec3& n, double solidAngle,
                    double cosBeta);

}  // namespace aokit
