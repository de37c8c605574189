#include "fields/GridFieldBake.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fields/OcclusionProbe.h"
#include "fields/RadialFieldEval.h"
#include "fields/SphereDirections.h"
#include "reference/EmbreeScene.h"
#include "reference/HemisphereSampler.h"
#include "reference/ParallelRows.h"

namespace aokit {

namespace {

std::vector<glm::dvec3> termDirections(FieldKind kind) {
  if (kind == FieldKind::Grid4) {
    const auto& t = tetrahedronDirections();
    return {t.begin(), t.end()};
  }
  // grid6 term order: -x, -y, -z, +x, +y, +z (the seed's minField then maxField).
  return {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
}

}  // namespace

double gridEdgeFade(int i, int n, double fadeCells) {
  const int e = std::min(i, n - 1 - i);
  if (e <= 0) return 0.0;
  if (!(fadeCells > 0.0)) return 1.0;
  return glslSmoothstep(0.0, fadeCells, static_cast<double>(e));
}

void blurGrid(std::vector<float>& values, int n, int channels) {
  const std::vector<float> in(values);
  auto at = [&](int i, int j, int k) { return ((static_cast<std::size_t>(k) * n + j) * n + i) * channels; };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        double sum[8] = {0};
        double wsum = 0.0;
        for (int dz = -1; dz <= 1; ++dz)
          for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx) {
              const int x = i + dx, y = j + dy, z = k + dz;
              if (x < 0 || y < 0 || z < 0 || x >= n || y >= n || z >= n) continue;
              const int zeros = (dx == 0) + (dy == 0) + (dz == 0);
              const double w = (zeros + 1) * (zeros + 1);
              wsum += w;
              for (int c = 0; c < channels; ++c) sum[c] += w * in[at(x, y, z) + c];
            }
        for (int c = 0; c < channels; ++c) values[at(i, j, k) + c] = static_cast<float>(sum[c] / wsum);
      }
}

GridField bakeGridField(const BakeMesh& input, const FieldBakeSettings& s, double radius, Falloff falloff,
                        const std::function<void(double)>& progress) {
  const TriangleMesh& mesh = input.mesh();
  validate(s);
  if (s.kind != FieldKind::Grid6 && s.kind != FieldKind::Grid4)
    throw std::invalid_argument("grid field bake: kind must be grid6 or grid4");
  if (s.resolution < 2) throw std::invalid_argument("grid field bake: resolution must be resolved (>= 2)");
  if (!(radius > 0.0) || !std::isfinite(radius)) throw std::invalid_argument("grid field bake: radius must be positive");
  const int n = s.resolution;
  GridField field;
  field.kind = s.kind;
  field.resolution = n;
  const Bounds b = mesh.bounds();
  const double pad = s.padding * radius;
  field.origin = b.min - glm::dvec3(pad);
  field.size = glm::max(b.max - b.min + glm::dvec3(2.0 * pad), glm::dvec3(1e-6 * std::max(radius, b.diagonal())));

  const EmbreeScene& scene = input.scene();
  const std::vector<glm::dvec3> dirs = termDirections(s.kind);
  const int terms = static_cast<int>(dirs.size());
  const std::vector<glm::dvec3> sphere = fibonacciSphere(s.gridRays);
  std::vector<float> values(field.pointCount() * terms, 0.0f);
  parallelRows(
      n * n, s.threads,
      [&](int row) {
        OcclusionProbe probe(scene, radius, falloff, sphere);
        const int j = row % n, k = row / n;
        for (int i = 0; i < n; ++i) {
          const std::size_t point = (static_cast<std::size_t>(k) * n + j) * n + i;
          const glm::dvec3 p = field.origin + (glm::dvec3(i, j, k) + 0.5) / static_cast<double>(n) * field.size;
          probe.trace(p, randomRotation(mix64(s.seed ^ 0x6772696400000000ull) ^ point * 0x9e3779b97f4a7c15ull));
          for (int t = 0; t < terms; ++t) {
            double sum = 0.0;
            for (int q = 0; q < probe.size(); ++q)
              sum += probe.weight(q) * std::max(0.0, glm::dot(probe.direction(q), dirs[t]));
            values[point * terms + t] = static_cast<float>(std::min(1.0, 4.0 * sum / probe.size()));
          }
        }
      },
      progress);
  scene.throwIfError("grid field bake");

  if (s.blur) blurGrid(values, n, terms);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double fade = gridEdgeFade(i, n, s.fadeCells) * gridEdgeFade(j, n, s.fadeCells) *
                            gridEdgeFade(k, n, s.fadeCells);
        const std::size_t point = (static_cast<std::size_t>(k) * n + j) * n + i;
        for (int t = 0; t < terms; ++t) values[point * terms + t] = static_cast<float>(values[point * terms + t] * fade);
      }

  if (s.kind == FieldKind::Grid4) {
    field.texels = std::move(values);
  } else {  // split into the negative and positive planes
    const std::size_t points = field.pointCount();
    field.texels.resize(points * 6);
    for (std::size_t p = 0; p < points; ++p)
      for (int c = 0; c < 3; ++c) {
        field.texels[p * 3 + c] = values[p * 6 + c];
        field.texels[(points + p) * 3 + c] = values[p * 6 + 3 + c];
      }
  }
  return field;
}

}  // namespace aokit
