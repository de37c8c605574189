#pragma once
// Joint bilateral upsampling of a low-resolution AO map (seed 004, section 7, eqs. 5-8), as pure
// weight functions and a CPU reference of the separable filter, for tests on synthetic buffers
// and as the oracle of the GPU stage. Every kernel is the Wendland w(t, h) of eq. 3.
//
// Full-resolution pixel x, low-resolution map h' at scale k (pixel y reads texel y/k =
// (floor(y.x/k), floor(y.y/k))), offsets d in [-m/2, m/2] (integer division) along one axis per pass:
//     h(x) = sum_y w_d w_n w_p w_h h'(y/k) / sum_y w_d w_n w_p w_h                       (eq. 5)
//     w_d = w(|x - y|, m)                      screen distance in pixels                  (eq. 6)
//     w_n = w(1 - <n(x), n'(y/k)>, h_n)        normals; the seed prints 1 + <,>, which
//                                              would weigh opposite normals most: a sign slip
//     w_p = w(|p(x) - p'(y/k)|, h_p)           world positions (seed: h_p = d_max = R)
//     w_h = w(|h'(x/k) - h'(y/k)|, h_h)        AO values (seed: h_h = 1)                  (eq. 7)
// n', p' are the G-buffer values where the low-resolution AO was computed (Kopf et al.'s joint
// upsampling). The seed writes n(y), p(y) of the full-resolution pixel; the two agree except at
// edges that cut a low-resolution texel, where the seed's form takes the AO of the texel's other
// side at full weight. w_h is left out (1) when x's own texel fails the normal or position test
// (its value belongs to another surface).
// Separable (eq. 8), at the low resolution across the pass: the horizontal pass filters each row
// of the low-resolution map at full horizontal resolution, for the pixels of the rows the map's
// texels stand for (rowSamples: W x ceil(H/k), row j = pixel row k j + (k - 1) / 2); the vertical
// pass filters those rows for every full-resolution pixel, reading row qy / k for window pixel qy,
// with the row's guide on the far side. In both passes the range weights depend only on the
// texel or row a window pixel reads, so a GPU sums them per texel (O(m / k) reads per pixel)
// with the domain weights of that texel's pixels added up: the same sum, in another order.
// Uncovered pixels and texels do not contribute; a pixel with no contributor stays uncovered.
#include <vector>

#include "reference/SurfaceSamples.h"

namespace aokit {

// The filter's parameters, all to be given (DeferredSettings.h holds the user-facing defaults).
struct BilateralParams {
  int filterSize = 0;           //!< m, full-resolution pixels, >= 1 (1 = nearest, no filtering)
  int scale = 0;                //!< k: full / low resolution, 1..8
  float normalSupport = 0.0f;   //!< h_n over 1 - <n, n'>, in (0, 2]
  float positionSupport = 0.0f; //!< h_p, world units, > 0
  float aoSupport = 0.0f;       //!< h_h, AO units, > 0
};

float bilateralDomainWeight(float pixels, int filterSize);
// The GPU passes' domain weights per tap (DeferredUpsampleFS.glsl): entry o + r + ds - 1 holds the
// sum of w(|o + t|, m) over t = 0..ds-1 with |o + t| <= r = m / 2, the weight of a texel whose
// first pixel lies o pixels from the filtered one; 2 r + ds entries.
std::vector<float> separableDomainWeights(int m, int ds);
float bilateralNormalWeight(const glm::vec3& nx, const glm::vec3& ny, float support);
float bilateralPositionWeight(const glm::vec3& px, const glm::vec3& py, float support);
float bilateralAOWeight(float ax, float ay, float support);

// The low-resolution G-buffer this reference assumes: texel (i, j) is full-resolution pixel
// (min(k i + (k - 1) / 2, W - 1), min(k j + (k - 1) / 2, H - 1)).
SurfaceSamples lowResolutionSamples(const SurfaceSamples& fullRes, int scale);

// The guide of the horizontal pass's output: pixel (x, min(k j + (k - 1) / 2, H - 1)) for row j.
SurfaceSamples rowSamples(const SurfaceSamples& fullRes, int scale);

// The separable joint bilateral upsampling of `lowAO` (computed on `lowG`, both ceil(W/k) x
// ceil(H/k)) to the size of `fullG` (W x H). Throws std::invalid_argument on bad parameters or
// sizes that do not match.
AOBuffer jointBilateralUpsample(const AOBuffer& lowAO, const SurfaceSamples& lowG, const SurfaceSamples& fullG,
                                const BilateralParams& params);

}  // namespace aokit
