#include "fields/SelfOcclusionBake.h"

#include <algorithm>
#include <stdexcept>

#include "fields/OcclusionProbe.h"
#include "reference/AOReference.h"
#include "reference/EmbreeScene.h"

namespace aokit {

std::vector<float> bakeVertexOcclusion(const BakeMesh& input, double radius, Falloff falloff, int rays,
                                       int threads, std::uint64_t seed, const std::function<void(double)>& progress,
                                       bool backSide) {
  const TriangleMesh& mesh = input.mesh();
  TriangleMesh withNormals;
  const TriangleMesh* m = &mesh;
  if (mesh.normals.size() != mesh.positions.size()) {
    withNormals = mesh;
    withNormals.computeNormals();
    m = &withNormals;
  }
  const EmbreeScene& scene = input.scene();  // normals do not enter the scene
  // Vertices as the "pixels" of a 256-wide image, so the reference's row-parallel loop applies.
  const int width = 256;
  const std::size_t count = m->positions.size();
  SurfaceSamples samples;
  samples.resize(width, static_cast<int>((count + width - 1) / width));
  for (std::size_t i = 0; i < count; ++i) {
    samples.position[i] = m->positions[i];
    samples.normal[i] = backSide ? -m->normals[i] : m->normals[i];
    samples.covered[i] = 1;
  }
  ReferenceOptions options;
  options.samples = rays;
  options.radius = radius;
  options.falloff = falloff;
  options.seed = seed;
  options.threads = threads;
  options.progress = progress;
  options.hemisphere = Hemisphere::Shading;  // per vertex: no one facet, the vertex normal's hemisphere
  const AOBuffer ao = computeReferenceAO(scene, samples, options);
  std::vector<float> out(count, 0.0f);
  for (std::size_t i = 0; i < count; ++i) out[i] = ao.covered[i] ? ao.ao[i] : 0.0f;
  return out;
}

}  // namespace aokit
