#include "render/BilateralUpsample.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "render/Wendland.h"

namespace aokit {

float bilateralDomainWeight(float pixels, int filterSize) { return wendland(pixels, static_cast<float>(filterSize)); }

std::vector<float> separableDomainWeights(int m, int ds) {
  const int r = m / 2;
  std::vector<float> out(static_cast<std::size_t>(2 * r + ds), 0.0f);
  for (int o = -r - ds + 1; o <= r; ++o) {
    float sum = 0.0f;
    for (int t = 0; t < ds; ++t)
      if (std::abs(o + t) <= r) sum += wendland(static_cast<float>(std::abs(o + t)), static_cast<float>(m));
    out[static_cast<std::size_t>(o + r + ds - 1)] = sum;
  }
  return out;
}

float bilateralNormalWeight(const glm::vec3& nx, const glm::vec3& ny, float support) {
  return wendland(std::max(0.0f, 1.0f - glm::dot(nx, ny)), support);
}

float bilateralPositionWeight(const glm::vec3& px, const glm::vec3& py, float support) {
  return wendland(glm::length(px - py), support);
}

float bilateralAOWeight(float ax, float ay, float support) { return wendland(ax - ay, support); }

SurfaceSamples lowResolutionSamples(const SurfaceSamples& full, int k) {
  if (k < 1) throw std::invalid_argument("bilateral: scale must be >= 1");
  full.validate();
  SurfaceSamples low;
  low.resize((full.width + k - 1) / k, (full.height + k - 1) / k);
  for (int j = 0; j < low.height; ++j)
    for (int i = 0; i < low.width; ++i) {
      const std::size_t src = full.index(std::min(k * i + (k - 1) / 2, full.width - 1),
                                         std::min(k * j + (k - 1) / 2, full.height - 1));
      const std::size_t dst = low.index(i, j);
      low.position[dst] = full.position[src];
      low.normal[dst] = full.normal[src];
      low.covered[dst] = full.covered[src];
    }
  return low;
}

SurfaceSamples rowSamples(const SurfaceSamples& full, int k) {
  if (k < 1) throw std::invalid_argument("bilateral: scale must be >= 1");
  full.validate();
  SurfaceSamples rows;
  rows.resize(full.width, (full.height + k - 1) / k);
  for (int j = 0; j < rows.height; ++j)
    for (int x = 0; x < full.width; ++x) {
      const std::size_t src = full.index(x, std::min(k * j + (k - 1) / 2, full.height - 1));
      const std::size_t dst = rows.index(x, j);
      rows.position[dst] = full.position[src];
      rows.normal[dst] = full.normal[src];
      rows.covered[dst] = full.covered[src];
    }
  return rows;
}

namespace {

void checkParams(const BilateralParams& p) {
  auto positive = [](float v) { return v > 0.0f && std::isfinite(v); };
  if (p.filterSize < 1) throw std::invalid_argument("bilateral: filterSize must be >= 1");
  if (p.scale < 1 || p.scale > 8) throw std::invalid_argument("bilateral: scale must be in 1..8");
  if (!positive(p.normalSupport) || p.normalSupport > 2.0f)
    throw std::invalid_argument("bilateral: normalSupport must be in (0, 2]");
  if (!positive(p.positionSupport)) throw std::invalid_argument("bilateral: positionSupport must be positive");
  if (!positive(p.aoSupport)) throw std::invalid_argument("bilateral: aoSupport must be positive");
}

void checkSizes(const AOBuffer& ao, const SurfaceSamples& g, int w, int h, const char* what) {
  ao.validate();
  g.validate();
  if (ao.width != w || ao.height != h || g.width != w || g.height != h)
    throw std::invalid_argument(std::string("bilateral: ") + what + " must be " + std::to_string(w) + " x " +
                                std::to_string(h) + ", got AO " + std::to_string(ao.width) + " x " +
                                std::to_string(ao.height) + " and G-buffer " + std::to_string(g.width) + " x " +
                                std::to_string(g.height));
}

// One pass along x or y over the output guide `g`; output (x, y) reads `src` (guide `srcG`) at
// (x / kx, y / ky), and its window's pixels q at (q.x / kx, q.y / ky).
AOBuffer pass(const AOBuffer& src, const SurfaceSamples& srcG, int kx, int ky, const SurfaceSamples& g,
              const BilateralParams& p, bool horizontal) {
  AOBuffer out;
  out.resize(g.width, g.height);
  const int r = p.filterSize / 2;
  for (int y = 0; y < g.height; ++y)
    for (int x = 0; x < g.width; ++x) {
      const std::size_t i = g.index(x, y);
      if (!g.covered[i]) continue;
      const glm::vec3 &px = g.position[i], &nx = g.normal[i];
      auto rangeGeometry = [&](std::size_t t) {
        return bilateralNormalWeight(nx, srcG.normal[t], p.normalSupport) *
               bilateralPositionWeight(px, srcG.position[t], p.positionSupport);
      };
      const std::size_t own = src.index(x / kx, y / ky);
      const bool useAO = src.covered[own] && rangeGeometry(own) > 0.0f;
      float sum = 0.0f, weights = 0.0f;
      for (int d = -r; d <= r; ++d) {
        // The window's full-resolution pixels, cut at the image's border (the output guide is full
        // resolution along the pass).
        const int qx = horizontal ? x + d : x, qy = horizontal ? y : y + d;
        if (qx < 0 || qy < 0 || qx >= g.width || qy >= g.height) continue;
        const std::size_t t = src.index(qx / kx, qy / ky);
        if (!src.covered[t]) continue;
        float w = bilateralDomainWeight(static_cast<float>(std::abs(d)), p.filterSize) * rangeGeometry(t);
        if (useAO) w *= bilateralAOWeight(src.ao[own], src.ao[t], p.aoSupport);
        sum += w * src.ao[t];
        weights += w;
      }
      if (weights > 0.0f) {
        out.ao[i] = sum / weights;
        out.covered[i] = 1;
      }
    }
  return out;
}

}  // namespace

AOBuffer jointBilateralUpsample(const AOBuffer& lowAO, const SurfaceSamples& lowG, const SurfaceSamples& fullG,
                                const BilateralParams& p) {
  checkParams(p);
  fullG.validate();
  checkSizes(lowAO, lowG, (fullG.width + p.scale - 1) / p.scale, (fullG.height + p.scale - 1) / p.scale,
             "the low-resolution AO map and its G-buffer");
  const SurfaceSamples rowG = rowSamples(fullG, p.scale);
  const AOBuffer rows = pass(lowAO, lowG, p.scale, 1, rowG, p, true);
  return pass(rows, rowG, 1, p.scale, fullG, p, false);
}

}  // namespace aokit
