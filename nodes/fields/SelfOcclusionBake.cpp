#include "fields/SelfOcclusionBake.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/BakeRefinement.h"
#include "fields/OcclusionProbe.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"

namespace aokit {
namespace {

// Points [from, split.pointCount()) baked around their normals (reversed for the back side).
std::vector<float> bakePoints(const BakeMesh& input, const CreaseSplit& split, std::size_t from, double radius,
                              Falloff falloff, int rays, int threads, std::uint64_t seed,
                              const std::function<void(double)>& progress, bool backSide) {
  const EmbreeScene& scene = input.scene();  // normals do not enter the scene
  // Points as the "pixels" of a 256-wide image, so the reference's row-parallel loop applies.
  const int width = 256;
  const std::size_t count = split.pointCount() - from;
  SurfaceSamples samples;
  samples.resize(width, static_cast<int>((count + width - 1) / width));
  for (std::size_t i = 0; i < count; ++i) {
    samples.position[i] = split.position(input.mesh(), from + i);
    samples.normal[i] = backSide ? -split.normals[from + i] : split.normals[from + i];
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

}  // namespace

std::vector<float> bakeVertexOcclusion(const BakeMesh& input, double radius, Falloff falloff, int rays,
                                       int threads, std::uint64_t seed, const std::function<void(double)>& progress,
                                       bool backSide) {
  // One value a point of the crease split: copies at creases bake around their own facets.
  return bakePoints(input, splitAtCreases(input.mesh()), 0, radius, falloff, rays, threads, seed, progress, backSide);
}

SelfOcclusion bakeSelfOcclusion(const BakeMesh& input, double radius, Falloff falloff, int rays, int sides,
                                int refinements, int threads, std::uint64_t seed, const std::function<void(double)>& progress) {
  SelfOcclusion out;
  out.points = splitAtCreases(input.mesh());
  std::vector<std::vector<float>> perSide(static_cast<std::size_t>(sides));
  // The first round takes most of the time: progress gives it 80 %, the refinements the rest.
  auto part = [&](double from, double share) {
    return [&progress, from, share](double f) {
      if (progress) progress(from + share * f);
    };
  };
  if (refinements < 0 || refinements > kMaxSelfRefinements)
    throw std::invalid_argument("self-occlusion: refinement rounds must be 0.." + std::to_string(kMaxSelfRefinements));
  std::size_t from = 0;
  for (int round = 0; round <= refinements; ++round) {
    const double first = refinements > 0 ? 0.8 : 1.0;  // of the progress
    const double start = round == 0 ? 0.0 : first + (1.0 - first) * (round - 1) / refinements;
    const double share = (round == 0 ? first : (1.0 - first) / refinements) / sides;
    for (int side = 0; side < sides; ++side) {
      // Each round its own seed: new points are not the first points' rays again.
      const std::vector<float> v = bakePoints(input, out.points, from, radius, falloff, rays, threads,
                                              seed + static_cast<std::uint64_t>(round), part(start + side * share, share),
                                              side == 1);
      perSide[static_cast<std::size_t>(side)].insert(perSide[static_cast<std::size_t>(side)].end(), v.begin(), v.end());
    }
    if (round == refinements) break;
    from = out.points.pointCount();
    const PointValue value = [&](int side, std::uint32_t p) { return perSide[static_cast<std::size_t>(side)][p]; };
    if (refineWhereValuesStep(out.points, input.mesh(), value, sides, kSelfRefineStep, radius / kSelfRefineMinEdge) == 0)
      break;
  }
  for (const std::vector<float>& v : perSide) out.values.insert(out.values.end(), v.begin(), v.end());
  if (progress) progress(1.0);
  return out;
}

CreaseSplit selfOcclusionPoints(const TriangleMesh& mesh, const std::vector<float>& values, int sides, double radius,
                                int refinements) {
  CreaseSplit points = splitAtCreases(mesh);
  const std::size_t total = sides > 0 ? values.size() / static_cast<std::size_t>(sides) : 0;
  auto mismatch = [&] {
    return std::invalid_argument("self-occlusion: " + std::to_string(values.size()) + " values do not fit the " +
                                 std::to_string(points.pointCount()) + " points of the mesh's refinement");
  };
  if (total * static_cast<std::size_t>(sides) != values.size()) throw mismatch();
  const PointValue value = [&](int side, std::uint32_t p) { return values[static_cast<std::size_t>(side) * total + p]; };
  for (int round = 0; round < refinements; ++round) {
    if (points.pointCount() > total) throw mismatch();
    if (refineWhereValuesStep(points, mesh, value, sides, kSelfRefineStep, radius / kSelfRefineMinEdge) == 0) break;
  }
  if (points.pointCount() != total) throw mismatch();
  return points;
}

}  // namespace aokit
