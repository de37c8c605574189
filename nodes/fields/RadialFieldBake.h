#pragma once
// Bakes a cube-map radial field (seed 000) with Embree.
//
// What the field estimates: the same quantity as the reference (reference/AOReference.h),
//   A(x, n) = 1/pi * integral over the hemisphere of V(x, w) k(d(x, w)) cos dw,
// with the scene's AO radius R and falloff k, which is 0 beyond R. The cap of Algorithm 1 is
// therefore fitted to falloff-weighted moments of what is visible within R:
//   Omega(x)   = integral over the sphere of V k(d) dw           (solid angle within R, weighted)
//   Upsilon(x) = normalize(integral over the sphere of V k(d) w dw)
// For binary k these are the solid angle and mean direction of the occluder parts closer than R;
// occluder parts beyond R do not count. For a sphere the directions within R still form a cap, so
// the field of a sphere is exact up to the fits. The evaluator then returns T_LUT[Omega, n.Upsilon],
// the cosine-weighted hemisphere integral of that cap. Beyond rMax = bounding radius + R nothing
// is within R, so the field ends there. The far fade (RadialField::fade) runs over a window given
// in R beyond the hull; how far a shadow reaches past the hull depends on the shape (R below a
// box's face, R / sin(elevation) along a direction grazing a plane), so by default the bake fits a
// third of the texels with each of a few windows ((0.5, 1.5), (0.7, 1.2), (1.5, 2.5), (3.75, 4) R)
// and keeps the one with the smallest residual. Measured at random points within the field
// (RMSE against the reference, N = 16): the compact windows win on a box (0.025 against 0.034) and
// the bunny, the one ending at the cull radius on a sphere (0.008 against 0.012) and a plane
// (0.086 against 0.17).
//
// Steps: centre = surface centroid; r0(w) from the hull's support planes (HullRadius.h). For each
// direction of a supersampled cube map (2N per face side, plus a margin beyond the face edges for
// the border texels), Omega and Upsilon are measured by rays over the whole sphere (OcclusionProbe)
// at radialSamples radii r0 + delta, delta geometric from R/100 to rMax - r0 (dense near the hull,
// where contact shadows vary fastest). Each stored texel (borders included, each at its own
// direction) then fits eq. 9 and eq. 10 (RadialFit.h) to the pooled samples of the 4x4 supersampled
// directions around it, weighted by a Gaussian of sigma = half a texel: low-pass filtering before
// sampling, as the seed prescribes, done on the data rather than on the fitted coefficients. The
// solid-angle fit includes the evaluator's far fade and weights each sample by (dA/dOmega)^2 of a
// facing cap, cos^2(alpha) floored at 0.1 (next to a flat face, where Omega ~ 2 pi, A hardly
// depends on Omega); the direction fit weights each sample by its Omega (far samples see little
// and their direction is noise). r0 is the Gaussian mean of the supersampled r0. C0 is kept inside the hull along the
// texel direction (C0.w <= 0.9 r0) so that C0 - r w never vanishes for r >= r0.
#include <functional>

#include "fields/BakeMesh.h"
#include "fields/FieldBakeSettings.h"
#include "fields/RadialField.h"

namespace aokit {

// settings.resolution must be resolved (> 0); radius > 0 in the mesh's units. progress gets the
// fraction done and may throw to cancel. Throws std::invalid_argument on bad input.
RadialField bakeRadialField(const BakeMesh& mesh, const FieldBakeSettings& settings, double radius, Falloff falloff,
                            const std::function<void(double)>& progress = {});

}  // namespace aokit
