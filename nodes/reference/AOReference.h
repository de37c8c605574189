#pragma once
// Ground-truth ambient occlusion by Embree ray casting from the rasterizer's own surface points.
//
// For each covered pixel with point x and normal n it estimates
//     A(x, n) = 1/pi * integral over the hemisphere of V(x, w) k(d(x, w)) cos(theta) dw
// where d is the distance to the first occluder along w and k the falloff (falloffWeight), 0 beyond
// the radius R. Directions are cosine-distributed, so the estimate is the mean of k(d) over the
// rays. Binary falloff needs only occlusion rays (rtcOccluded1, tfar = R); the others need the hit
// distance (rtcIntersect1). Samples are stratified (HemisphereSampler) and decorrelated per pixel,
// and rays start from robust origins (SurfaceRay). Results depend on (samples, seed) only, never
// on the thread count. Pixels of props that receive no AO (SurfaceSamples::receives) get 0.
// The hemisphere and the cosine are the hit facet's (Hemisphere::Geometric, default) or the
// G-buffer's shading normal's (Hemisphere::Shading); see SurfaceRay.h.
//
// With quantity Transfer it estimates 1 - W instead, W the ambient transfer function of seed 003,
// eq. 6, per colour c on the same rays: with the fuzzy membership mu = 1 - k(d) (1 for a ray that
// leaves R open) and a_c the albedo of the geometry the ray hits,
//     W_c = mean(mu) / (1 - mean((1 - mu) a_c)),
// reported as the mean of 1 - W_c over the three colours (what the methods' read-back reports).
// Its standard error is the ratio estimator's (delta method), averaged over colours.
#include <cstdint>
#include <functional>

#include "core/AOScene.h"
#include "reference/EmbreeScene.h"
#include "reference/SurfaceRay.h"
#include "reference/SurfaceSamples.h"

namespace aokit {

struct ReferenceOptions {
  int samples = 256;                  //!< rays per pixel, >= 1
  double radius = 1.0;                //!< AO radius R in world units, > 0 (usually AOScene::aoRadius())
  Falloff falloff = Falloff::Binary;  //!< weight of an occluder at distance d (usually AOScene::falloff())
  std::uint64_t seed = 1;             //!< same seed, same samples -> bit-identical output
  int threads = 0;                    //!< worker threads; 0 = hardware concurrency
  float rayOffset = 0.0f;             //!< origin offset in world units; 0 = defaultRayOffset()
  AOQuantity quantity = AOQuantity::Occlusion;  //!< occlusion A, or 1 - W (ambient transfer)
  Hemisphere hemisphere = Hemisphere::Geometric;  //!< around the hit facet's normal, or the shading normal
  std::function<void(double)> progress;  //!< fraction done, on the calling thread; throw to cancel
};

// Options for a scene's own AO radius and falloff.
ReferenceOptions sceneReferenceOptions(const AOScene& root, int samples, std::uint64_t seed);

struct ReferenceStats {
  double raysPerSecond = 0.0;  // AO rays / seconds
  double seconds = 0.0;        // wall time of the ray-casting phase (probes and sampling included)
  std::uint64_t rays = 0;      // AO rays cast (samples per valid covered pixel; probe rays not counted)
};

// AO, coverage and standard error for every pixel of `samples`. A covered pixel with a zero or
// non-finite normal or position comes back uncovered. Throws std::invalid_argument on bad
// options or buffer sizes, std::runtime_error on an Embree error.
AOBuffer computeReferenceAO(const EmbreeScene& scene, const SurfaceSamples& samples, const ReferenceOptions& options,
                            ReferenceStats* stats = nullptr);

// Rays per second of Embree alone on the same rays computeReferenceAO casts (same origins,
// directions, tfar = R, the same Embree calls: occlusion or intersection, stream or single) from
// the same number of threads, with the rays generated beforehand and not timed: the ceiling the
// reference is compared against. Uses every k-th row (all rays of its covered pixels), k chosen so
// that about maxRays rays are held in memory.
double measureRawThroughput(const EmbreeScene& scene, const SurfaceSamples& samples, const ReferenceOptions& options,
                            std::uint64_t maxRays = 1u << 21);

// The reference's throughput set against Embree's alone on identical rays: both on the same row
// subset (about maxRays rays), alternating runs, best of three each (other jobs share the machine).
struct ThroughputComparison {
  double referenceRaysPerSecond = 0.0, rawRaysPerSecond = 0.0;
  std::uint64_t rays = 0;  // rays of the subset
  double ratio() const { return rawRaysPerSecond > 0.0 ? referenceRaysPerSecond / rawRaysPerSecond : 0.0; }
};
ThroughputComparison compareThroughput(const EmbreeScene& scene, const SurfaceSamples& samples,
                                       const ReferenceOptions& options, std::uint64_t maxRays = 1u << 21);

// Every k-th row of the samples, as a smaller buffer (rows 0, k, 2k, ...): a cheaper set of
// pixels for throughput and noise measurements.
SurfaceSamples everyKthRow(const SurfaceSamples& samples, int k);

}  // namespace aokit
