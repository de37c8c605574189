#include "screen/PoissonDiscSet.h"

#include <cmath>
#include <limits>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

namespace aokit {

namespace {

// splitmix64: a tiny generator whose output is fixed by its definition, unlike std:: distributions.
struct SplitMix {
  std::uint64_t state;
  std::uint64_t next() {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }  // [0, 1)
};

// Shortest offset from a to b on the unit torus, each component in [-0.5, 0.5].
glm::dvec3 wrapDelta(const glm::dvec3& a, const glm::dvec3& b) {
  glm::dvec3 d = b - a;
  return d - glm::floor(d + 0.5);
}

glm::dvec3 wrapPoint(const glm::dvec3& p) { return p - glm::floor(p); }

}  // namespace

std::vector<glm::dvec3> lloydPoissonDisc(int n, const LloydOptions& o) {
  if (n < 1) throw std::invalid_argument("Poisson disc: need at least 1 point, got " + std::to_string(n));
  if (o.iterations < 0 || o.probesPerPoint < 8)
    throw std::invalid_argument("Poisson disc: iterations must be >= 0 and probesPerPoint >= 8");
  SplitMix rng{o.seed};
  std::vector<glm::dvec3> sites(n);
  for (auto& s : sites) s = {rng.uniform(), rng.uniform(), rng.uniform()};

  // Quadrature points for the Voronoi cells: a jittered grid, so every region of the cube is probed.
  const int g = std::max(2, static_cast<int>(std::ceil(std::cbrt(double(n) * o.probesPerPoint))));
  std::vector<glm::dvec3> probes;
  probes.reserve(static_cast<std::size_t>(g) * g * g);
  for (int z = 0; z < g; ++z)
    for (int y = 0; y < g; ++y)
      for (int x = 0; x < g; ++x)
        probes.push_back(glm::dvec3(x + rng.uniform(), y + rng.uniform(), z + rng.uniform()) / double(g));

  std::vector<glm::dvec3> sum(n);
  std::vector<int> count(n);
  for (int it = 0; it < o.iterations; ++it) {
    std::fill(sum.begin(), sum.end(), glm::dvec3(0.0));
    std::fill(count.begin(), count.end(), 0);
    for (const auto& p : probes) {
      int best = 0;
      double bestD = std::numeric_limits<double>::max();
      for (int i = 0; i < n; ++i) {
        const glm::dvec3 d = wrapDelta(sites[i], p);
        const double d2 = glm::dot(d, d);
        if (d2 < bestD) bestD = d2, best = i;
      }
      sum[best] += wrapDelta(sites[best], p);  // offsets from the site: centroids wrap correctly
      ++count[best];
    }
    for (int i = 0; i < n; ++i)
      if (count[i]) sites[i] = wrapPoint(sites[i] + sum[i] / double(count[i]));
  }
  return sites;
}

const std::vector<glm::dvec3>& cachedPoissonDisc(int n) {
  static std::mutex mutex;
  static std::map<int, std::vector<glm::dvec3>> cache;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, lloydPoissonDisc(n)).first;
  return it->second;
}

double minToroidalDistance(const std::vector<glm::dvec3>& points) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < points.size(); ++i)
    for (std::size_t j = i + 1; j < points.size(); ++j)
      best = std::min(best, glm::length(wrapDelta(points[i], points[j])));
  return best;
}

}  // namespace aokit
