#include "bench/SceneReferences.h"

#include <cmath>

#include "core/Progress.h"
#include "reference/Falloff.h"
#include "reference/Metrics.h"

namespace aokit {

SceneReferences::SceneReferences(const Scene& scene, const SurfaceSamples& surfaces, int samples, std::uint64_t seed,
                                 bool progress)
    : scene_(scene), surfaces_(surfaces), samples_(samples), seed_(seed), progress_(progress), embree_(*scene.root) {}

const SceneReferences::Reference& SceneReferences::get(AOQuantity quantity, Falloff falloff) {
  const auto key = std::make_pair(static_cast<int>(quantity), static_cast<int>(falloff));
  auto it = cache_.find(key);
  if (it != cache_.end()) return it->second;

  ReferenceOptions opt = sceneReferenceOptions(*scene_.root, samples_, seed_);
  opt.falloff = falloff;
  opt.quantity = quantity;
  const std::string what = (quantity == AOQuantity::Transfer ? "transfer " : "") + falloffName(falloff);
  Reference ref;
  {
    Progress progress("reference " + scene_.name + " (" + what + ")", progress_);
    opt.progress = progress.reporter();
    ReferenceStats stats;
    ref.ao = computeReferenceAO(embree_, surfaces_, opt, &stats);
    progress.done();
    ref.seconds = stats.seconds;
    ref.raysPerSecond = stats.raysPerSecond;
  }
  ref.stdErr = meanStandardError(ref.ao);

  // The measured noise floor: an independent estimate of the same pixels (another seed) on every
  // k-th row; two estimates of equal variance differ by sqrt 2 times one's error.
  ReferenceOptions second = opt;
  second.seed = seed_ + 0x9e3779b97f4a7c15ull;
  second.progress = nullptr;
  const SurfaceSamples rows = everyKthRow(surfaces_, kNoiseRowStride);
  const AOBuffer other = computeReferenceAO(embree_, rows, second);
  double sumSq = 0.0;
  std::size_t n = 0;
  for (int y = 0; y < rows.height; ++y)
    for (int x = 0; x < rows.width; ++x) {
      const std::size_t j = rows.index(x, y), i = surfaces_.index(x, y * kNoiseRowStride);
      if (!other.covered[j] || !ref.ao.covered[i]) continue;
      const double d = static_cast<double>(ref.ao.ao[i]) - other.ao[j];
      sumSq += d * d;
      ++n;
    }
  ref.noise = n ? std::sqrt(sumSq / n) / std::sqrt(2.0) : 0.0;
  return cache_.emplace(key, std::move(ref)).first->second;
}

ReferenceSummary SceneReferences::summary(bool measureThroughput) {
  const Reference& ref = get(AOQuantity::Occlusion, scene_.root->falloff());
  ReferenceSummary s;
  s.scene = scene_.name;
  s.samples = samples_;
  s.seconds = ref.seconds;
  s.raysPerSecond = ref.raysPerSecond;
  s.stdErr = ref.stdErr;
  s.noise = ref.noise;
  s.noiseRowStride = kNoiseRowStride;
  s.bvhSeconds = embree_.stats().buildSeconds;
  s.bvhBytes = embree_.stats().memoryBytes;
  s.triangles = embree_.stats().triangles;
  if (measureThroughput) {
    const ThroughputComparison c =
        compareThroughput(embree_, surfaces_, sceneReferenceOptions(*scene_.root, samples_, seed_));
    s.sameRaysReference = c.referenceRaysPerSecond;
    s.sameRaysEmbree = c.rawRaysPerSecond;
  }
  return s;
}

}  // namespace aokit
