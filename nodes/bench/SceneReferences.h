#pragma once
// The references one scene's bench rows are judged against, each computed when first asked for:
// one per (quantity, falloff), on the same G-buffer and the same rays (one Embree scene). With each
// comes its noise floor twice: the formula's (RMS of the per-pixel standard error) and the measured
// one (a second reference with another seed over every k-th row; RMS difference / sqrt 2).
#include <map>
#include <utility>

#include "bench/BenchResult.h"
#include "core/Scene.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"

namespace aokit {

class SceneReferences {
 public:
  static constexpr int kNoiseRowStride = 4;

  SceneReferences(const Scene& scene, const SurfaceSamples& surfaces, int samples, std::uint64_t seed,
                  bool progress);

  struct Reference {
    AOBuffer ao;
    double seconds = 0.0, raysPerSecond = 0.0;
    double stdErr = 0.0, noise = 0.0;
  };
  const Reference& get(AOQuantity quantity, Falloff falloff);

  // The scene's own reference (occlusion, the scene's falloff) as a report line; with
  // measureThroughput, the reference against Embree alone on identical rays.
  ReferenceSummary summary(bool measureThroughput);
  const EmbreeScene& embree() const { return embree_; }

 private:
  const Scene& scene_;
  const SurfaceSamples& surfaces_;
  int samples_;
  std::uint64_t seed_;
  bool progress_;
  EmbreeScene embree_;
  std::map<std::pair<int, int>, Reference> cache_;
};

}  // namespace aokit
