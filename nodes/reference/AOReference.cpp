#include "reference/AOReference.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/Falloff.h"
#include "reference/HemisphereSampler.h"
#include "reference/ParallelRows.h"
#include "reference/SurfaceRay.h"

namespace aokit {

namespace {

void validateOptions(const ReferenceOptions& o) {
  if (o.samples < 1)
    throw std::invalid_argument("reference AO: samples must be >= 1, got " + std::to_string(o.samples));
  if (!(o.radius > 0.0) || !std::isfinite(o.radius))
    throw std::invalid_argument("reference AO: radius must be positive and finite");
  if (!(o.rayOffset >= 0.0f) || !std::isfinite(o.rayOffset))
    throw std::invalid_argument("reference AO: rayOffset must be >= 0 and finite");
}

RTCRay makeRay(const glm::vec3& o, const glm::vec3& d, float tfar) {
  RTCRay r;
  r.org_x = o.x;
  r.org_y = o.y;
  r.org_z = o.z;
  r.tnear = 0.0f;  // the origin is already offset off the surface
  r.dir_x = d.x;
  r.dir_y = d.y;
  r.dir_z = d.z;
  r.time = 0.0f;
  r.tfar = tfar;
  r.mask = ~0u;
  r.id = 0;
  r.flags = 0;
  return r;
}

// Per-pixel mean and standard error of the ray weights.
struct Estimate {
  double mean, standardError;
};

Estimate estimate(double sum, double sumSq, int n) {
  const double mean = sum / n;
  // Sample std / sqrt(n) is the error of independent samples; stratification makes the true error
  // smaller, so this is a conservative bound. One sample has no spread: report the worst case for
  // a value in [0, 1] (std 0.5).
  if (n < 2) return {mean, 0.5};
  const double var = std::max(0.0, (sumSq - sum * mean) / (n - 1));
  return {mean, std::sqrt(var / n)};
}

// Rays are traced in batches through Embree's stream API (rtcOccluded1M / rtcIntersect1M), which
// measured ~1.3x faster than one rtcOccluded1 call per ray for a pixel's incoherent hemisphere rays
// on AVX-512; builds without stream support get the same loop of single-ray calls. The reference
// and the raw-throughput measurement both trace through these two functions.
constexpr int kBatch = 256;

void traceOccluded(const EmbreeScene& scene, RTCRay* rays, int count, bool stream) {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  if (stream) {
    rtcOccluded1M(scene.scene(), &ctx, rays, count, sizeof(RTCRay));
  } else {
    for (int k = 0; k < count; ++k) rtcOccluded1(scene.scene(), &ctx, &rays[k]);
  }
}

void traceIntersect(const EmbreeScene& scene, RTCRayHit* hits, int count, bool stream) {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  if (stream) {
    rtcIntersect1M(scene.scene(), &ctx, hits, count, sizeof(RTCRayHit));
  } else {
    for (int k = 0; k < count; ++k) rtcIntersect1(scene.scene(), &ctx, &hits[k]);
  }
}

// Binary-falloff occlusion needs only "is anything closer than R": occlusion rays.
bool occlusionRaysSuffice(const ReferenceOptions& o) {
  return o.falloff == Falloff::Binary && o.quantity == AOQuantity::Occlusion;
}

void resetHit(RTCRayHit& h) {
  h.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  h.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
}

struct Tracer {
  const EmbreeScene& scene;
  const HemisphereSampler& sampler;
  const ReferenceOptions& options;
  bool stream;
  std::vector<RTCRay> rays = std::vector<RTCRay>(occlusionRaysSuffice(options) ? kBatch : 0);
  std::vector<RTCRayHit> hits = std::vector<RTCRayHit>(occlusionRaysSuffice(options) ? 0 : kBatch);

  Estimate pixel(const SurfaceRay& sr, const PixelShift& shift) {
    return options.quantity == AOQuantity::Transfer ? transfer(sr, shift) : occlusion(sr, shift);
  }

  // Mean of k(d) over the rays.
  Estimate occlusion(const SurfaceRay& sr, const PixelShift& shift) {
    const float tfar = static_cast<float>(options.radius);
    const int n = sampler.size();
    double sum = 0.0, sumSq = 0.0;
    for (int first = 0; first < n; first += kBatch) {
      const int count = std::min(kBatch, n - first);
      if (occlusionRaysSuffice(options)) {
        for (int k = 0; k < count; ++k)
          rays[k] = makeRay(sr.origin, sr.toWorld(sampler.localDirection(first + k, shift)), tfar);
        traceOccluded(scene, rays.data(), count, stream);
        int hit = 0;
        for (int k = 0; k < count; ++k) hit += rays[k].tfar < 0.0f;  // Embree marks occluded rays with tfar = -inf
        sum += hit;
        sumSq += hit;
      } else {
        for (int k = 0; k < count; ++k) {
          hits[k].ray = makeRay(sr.origin, sr.toWorld(sampler.localDirection(first + k, shift)), tfar);
          resetHit(hits[k]);
        }
        traceIntersect(scene, hits.data(), count, stream);
        for (int k = 0; k < count; ++k) {
          if (hits[k].hit.geomID == RTC_INVALID_GEOMETRY_ID) continue;
          const double w = falloffWeight(options.falloff, hits[k].ray.tfar, options.radius);  // unit dirs: tfar = d
          sum += w;
          sumSq += w * w;
        }
      }
    }
    return estimate(sum, sumSq, n);
  }

  // 1 - W of seed 003's eq. 6 per colour, averaged; the ratio estimator's standard error.
  Estimate transfer(const SurfaceRay& sr, const PixelShift& shift) {
    const float tfar = static_cast<float>(options.radius);
    const int n = sampler.size();
    std::vector<double> mu(n);
    std::vector<glm::dvec3> bounce(n);  // (1 - mu) a per ray
    for (int first = 0; first < n; first += kBatch) {
      const int count = std::min(kBatch, n - first);
      for (int k = 0; k < count; ++k) {
        hits[k].ray = makeRay(sr.origin, sr.toWorld(sampler.localDirection(first + k, shift)), tfar);
        resetHit(hits[k]);
      }
      traceIntersect(scene, hits.data(), count, stream);
      for (int k = 0; k < count; ++k) {
        const RTCRayHit& h = hits[k];
        const bool hit = h.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        const double occ = hit ? falloffWeight(options.falloff, h.ray.tfar, options.radius) : 0.0;
        mu[first + k] = 1.0 - occ;
        bounce[first + k] = hit ? occ * glm::dvec3(scene.instances()[h.hit.geomID].albedo) : glm::dvec3(0.0);
      }
    }
    double meanMu = 0.0;
    glm::dvec3 meanBounce(0.0);
    for (int i = 0; i < n; ++i) {
      meanMu += mu[i];
      meanBounce += bounce[i];
    }
    meanMu /= n;
    meanBounce /= n;
    double result = 0.0, error = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double denominator = 1.0 - meanBounce[c];  // > 0: albedo <= 1 and mu >= 0
      const double W = denominator > 0.0 ? meanMu / denominator : 1.0;
      // Ratio estimator y/x with y = mu, x = 1 - bounce: var ~ var(y - W x) / (n x^2).
      double var = 0.0;
      for (int i = 0; i < n; ++i) {
        const double r = mu[i] - W * (1.0 - bounce[i][c]);
        var += r * r;
      }
      var = n > 1 ? var / (n - 1) : 0.25;
      result += 1.0 - std::min(1.0, W);
      error += denominator > 0.0 ? std::sqrt(var / n) / denominator : 0.5;
    }
    return {result / 3.0, error / 3.0};
  }
};

double since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

}  // namespace

AOBuffer computeReferenceAO(const EmbreeScene& scene, const SurfaceSamples& samples, const ReferenceOptions& options,
                            ReferenceStats* stats) {
  validateOptions(options);
  samples.validate();
  const HemisphereSampler sampler(options.samples);
  if (samples.receives.size() != samples.pixelCount()) throw std::invalid_argument("reference AO: receives mask missing");
  AOBuffer out;
  out.resize(samples.width, samples.height, true);
  std::vector<std::uint64_t> rowRays(samples.height, 0);
  const bool stream = rtcGetDeviceProperty(scene.device(), RTC_DEVICE_PROPERTY_RAY_STREAM_SUPPORTED) != 0;

  const auto start = std::chrono::steady_clock::now();
  parallelRows(
      samples.height, options.threads,
      [&](int y) {
        Tracer tracer{scene, sampler, options, stream};
        for (int x = 0; x < samples.width; ++x) {
          const std::size_t i = samples.index(x, y);
          if (!samples.covered[i]) continue;
          if (!samples.receives[i]) {  // a prop that receives no AO: 0, exactly as the methods write it
            out.covered[i] = 1;
            continue;
          }
          const SurfaceRay sr = makeSurfaceRay(scene, samples.position[i], samples.normal[i], options.rayOffset, options.hemisphere);
          if (!sr.valid) continue;
          const Estimate e = tracer.pixel(sr, HemisphereSampler::pixelShift(i, options.seed));
          out.ao[i] = static_cast<float>(e.mean);
          out.standardError[i] = static_cast<float>(e.standardError);
          out.covered[i] = 1;
          rowRays[y] += static_cast<std::uint64_t>(options.samples);
        }
      },
      options.progress);
  const double seconds = since(start);
  scene.throwIfError("reference AO");

  if (stats) {
    stats->seconds = seconds;
    stats->rays = 0;
    for (auto r : rowRays) stats->rays += r;
    stats->raysPerSecond = seconds > 0.0 ? stats->rays / seconds : 0.0;
  }
  return out;
}

double measureRawThroughput(const EmbreeScene& scene, const SurfaceSamples& samples, const ReferenceOptions& options,
                            std::uint64_t maxRays) {
  validateOptions(options);
  samples.validate();
  const HemisphereSampler sampler(options.samples);
  const auto n = static_cast<std::uint64_t>(options.samples);
  const bool occlusionOnly = occlusionRaysSuffice(options);
  const bool stream = rtcGetDeviceProperty(scene.device(), RTC_DEVICE_PROPERTY_RAY_STREAM_SUPPORTED) != 0;

  // Whole rows, evenly spaced: neighbouring pixels stay neighbours, so the rays keep the same
  // coherence (and cache behaviour) as in computeReferenceAO.
  std::uint64_t coveredCount = 0;
  for (std::size_t i = 0; i < samples.pixelCount(); ++i) coveredCount += samples.covered[i] && samples.receives[i];
  if (coveredCount == 0) throw std::invalid_argument("raw throughput: no covered pixels");
  const std::uint64_t total = coveredCount * n;
  maxRays = std::max<std::uint64_t>(maxRays, 1);
  const int rowStride = static_cast<int>(std::max<std::uint64_t>(1, (total + maxRays - 1) / maxRays));

  // Untimed: the exact rays computeReferenceAO casts for the chosen pixels.
  std::vector<RTCRayHit> rays;
  rays.reserve(std::min<std::uint64_t>(total, maxRays + static_cast<std::uint64_t>(samples.width) * n));
  const float tfar = static_cast<float>(options.radius);
  for (int y = 0; y < samples.height; y += rowStride)
    for (int x = 0; x < samples.width; ++x) {
      const std::size_t i = samples.index(x, y);
      if (!samples.covered[i] || !samples.receives[i]) continue;
      const SurfaceRay sr = makeSurfaceRay(scene, samples.position[i], samples.normal[i], options.rayOffset, options.hemisphere);
      if (!sr.valid) continue;
      const PixelShift shift = HemisphereSampler::pixelShift(i, options.seed);
      for (int s = 0; s < options.samples; ++s) {
        RTCRayHit h;
        h.ray = makeRay(sr.origin, sr.toWorld(sampler.localDirection(s, shift)), tfar);
        resetHit(h);
        rays.push_back(h);
      }
    }
  if (rays.empty()) throw std::invalid_argument("raw throughput: no valid covered pixels");
  std::vector<RTCRay> occlusionRays;
  if (occlusionOnly) {
    occlusionRays.reserve(rays.size());
    for (const auto& h : rays) occlusionRays.push_back(h.ray);
  }

  // Same pool shape and batch size as the reference: chunks of rays play the role of rows.
  const std::size_t chunk = 4096;
  const int chunks = static_cast<int>((rays.size() + chunk - 1) / chunk);
  const auto start = std::chrono::steady_clock::now();
  parallelRows(chunks, options.threads, [&](int c) {
    const std::size_t end = std::min(rays.size(), (c + 1) * chunk);
    for (std::size_t r = c * chunk; r < end; r += kBatch) {
      const int count = static_cast<int>(std::min<std::size_t>(kBatch, end - r));
      if (occlusionOnly) traceOccluded(scene, &occlusionRays[r], count, stream);
      else traceIntersect(scene, &rays[r], count, stream);
    }
  });
  const double seconds = since(start);
  scene.throwIfError("raw throughput");
  return seconds > 0.0 ? rays.size() / seconds : 0.0;
}

SurfaceSamples everyKthRow(const SurfaceSamples& samples, int k) {
  if (k < 1) throw std::invalid_argument("everyKthRow: k must be at least 1");
  samples.validate();
  SurfaceSamples out;
  out.resize(samples.width, (samples.height + k - 1) / k);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      const std::size_t from = samples.index(x, y * k), to = out.index(x, y);
      out.position[to] = samples.position[from];
      out.normal[to] = samples.normal[from];
      out.covered[to] = samples.covered[from];
      out.receives[to] = samples.receives[from];
    }
  return out;
}

ThroughputComparison compareThroughput(const EmbreeScene& scene, const SurfaceSamples& samples,
                                       const ReferenceOptions& options, std::uint64_t maxRays) {
  std::uint64_t coveredCount = 0;
  for (std::size_t i = 0; i < samples.pixelCount(); ++i) coveredCount += samples.covered[i] && samples.receives[i];
  const std::uint64_t total = coveredCount * static_cast<std::uint64_t>(std::max(1, options.samples));
  const int stride = static_cast<int>(std::max<std::uint64_t>(1, (total + maxRays - 1) / std::max<std::uint64_t>(1, maxRays)));
  const SurfaceSamples subset = everyKthRow(samples, stride);
  ReferenceOptions quiet = options;
  quiet.progress = nullptr;
  ThroughputComparison c;
  for (int round = 0; round < 3; ++round) {
    ReferenceStats stats;
    computeReferenceAO(scene, subset, quiet, &stats);
    c.rays = stats.rays;
    c.referenceRaysPerSecond = std::max(c.referenceRaysPerSecond, stats.raysPerSecond);
    c.rawRaysPerSecond = std::max(c.rawRaysPerSecond, measureRawThroughput(scene, subset, quiet, stats.rays + 1));
  }
  return c;
}

ReferenceOptions sceneReferenceOptions(const AOScene& root, int samples, std::uint64_t seed) {
  ReferenceOptions opt;
  opt.samples = samples;
  opt.radius = root.aoRadius();
  opt.falloff = root.falloff();
  opt.seed = seed;
  return opt;
}

}  // namespace aokit
