#include "fields/SelfOcclusionBake.h"

#include <algorithm>
#include <stdexcept>

#include "core/CreaseSplit.h"
#include "fields/OcclusionProbe.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"

namespace aokit {

std::vector<float> bakeVertexOcclusion(const BakeMesh& input, double radius, Falloff falloff, int rays,
                                       int threads, std::uint64_t seed, const std::function<void(double)>& progress,
                                       bool backSide) {
  // One value a point of the crease split: copies at creases bake around their own facets.
  const CreaseSplit split = splitAtCreases(input.mesh());
  const EmbreeScene& scene = input.scene();  // normals do not enter the scene
  // Points as the "pixels" of a 256-wide image, so the reference's row-parallel loop applies.
  const int width = 256;
  const std::size_t count = split.pointCount();
  SurfaceSamples samples;
  samples.resize(width, static_cast<int>((count + width - 1) / width));
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t vertex = i < split.vertexCount ? i : split.origin[i - split.vertexCount];
    samples.position[i] = input.mesh().positions[vertex];
    samples.normal[i] = backSide ? -split.normals[i] : split.normals[i];
    samples.covered[i] = 1;
  }
  ReferenceOptions options;
  options.samples = rays;
  options.radius = radius;
  options.falloff = falloff;
  options.seed = seed;
  options.threads = threads;
  options.progress = progress;
  options.hemisphere = Hemisphere::Shading;  // the sample's normal: the vertex's, or a copy's facets'
  const AOBuffer ao = computeReferenceAO(scene, samples, options);
  std::vector<float> out(count, 0.0f);
  for (std::size_t i = 0; i < count; ++i) out[i] = ao.covered[i] ? ao.ao[i] : 0.0f;
  return out;
}

}  // namespace aokit
