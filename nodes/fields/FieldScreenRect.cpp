#include "fields/FieldScreenRect.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace aokit {

TexelRect sphereTexelRect(const glm::dvec3& c, double r, const TargetGeometry& t) {
  TexelRect full{0, 0, t.targetWidth - 1, t.targetHeight - 1};
  if (!(r >= 0.0) || !std::isfinite(r) || !std::isfinite(c.x + c.y + c.z)) return full;
  double nx0 = 1e300, nx1 = -1e300, ny0 = 1e300, ny1 = -1e300;
  int behind = 0;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec4 v(c.x + ((i & 1) ? r : -r), c.y + ((i & 2) ? r : -r), c.z + ((i & 4) ? r : -r), 1.0);
    auto row = [&](int k) { return t.clip[k][0] * v.x + t.clip[k][1] * v.y + t.clip[k][2] * v.z + t.clip[k][3]; };
    const double w = row(2);
    if (!(w > 1e-12)) {
      ++behind;
      continue;
    }
    const double x = row(0) / w, y = row(1) / w;
    nx0 = std::min(nx0, x);
    nx1 = std::max(nx1, x);
    ny0 = std::min(ny0, y);
    ny1 = std::max(ny1, y);
  }
  if (behind == 8) return {};
  if (behind > 0) return full;
  // G-buffer texels whose centres lie in the NDC range, then the target texels standing for them.
  auto texels = [](double n0, double n1, int size, int guard, int screen, int ds, int target, int& c0, int& c1) {
    const double g0 = std::floor((n0 + 1.0) * 0.5 * size - 0.5), g1 = std::ceil((n1 + 1.0) * 0.5 * size - 0.5);
    const double s0 = g0 - guard, s1 = std::min(g1 - guard, static_cast<double>(screen - 1));
    if (s1 < 0.0 || s0 > screen - 1) return false;
    c0 = static_cast<int>(std::max(0.0, std::floor(s0 / ds) - 1.0));
    c1 = static_cast<int>(std::min(static_cast<double>(target - 1), std::ceil(s1 / ds) + 1.0));
    // The last texel stands for the screen's last pixel (min(c ds, screen - 1)).
    if (s1 >= screen - 1) c1 = target - 1;
    return c0 <= c1;
  };
  TexelRect out;
  if (!texels(nx0, nx1, t.gbufferWidth, t.guardX, t.screenWidth, t.downsample, t.targetWidth, out.x0, out.x1) ||
      !texels(ny0, ny1, t.gbufferHeight, t.guardY, t.screenHeight, t.downsample, t.targetHeight, out.y0, out.y1))
    return {};
  return out;
}

namespace {

// View-space point at NDC (x, y) and view z (DeferredCommon.glsl's aoUnproject).
glm::dvec3 unproject(const TargetGeometry& t, double nx, double ny, double z) {
  const double w = t.clip[2][2] * z + t.clip[2][3];
  return {(nx * w - t.clip[0][2] * z - t.clip[0][3]) / t.clip[0][0],
          (ny * w - t.clip[1][2] * z - t.clip[1][3]) / t.clip[1][1], z};
}

// NDC of the centre of the G-buffer texel that AO-target texel c stands for, along one axis.
double texelNdc(int c, int ds, int screen, int guard, int size) {
  const int g = std::min(c * ds, screen - 1) + guard;
  return (g + 0.5) / size * 2.0 - 1.0;
}

}  // namespace

std::vector<TexelRect> sphereTexelRuns(const glm::dvec3& c, double r, const TargetGeometry& t, const TileDepths& tiles) {
  std::vector<TexelRect> runs;
  const TexelRect rect = sphereTexelRect(c, r, t);
  if (rect.empty() || tiles.tile < 1) return runs;
  const int n = tiles.tile;
  std::vector<TexelRect> previous, current;
  auto flush = [&](std::vector<TexelRect>& rows) {
    runs.insert(runs.end(), rows.begin(), rows.end());
    rows.clear();
  };
  for (int ty = rect.y0 / n; ty <= rect.y1 / n && ty < tiles.tilesY; ++ty) {
    current.clear();
    const int y0 = std::max(rect.y0, ty * n), y1 = std::min(rect.y1, ty * n + n - 1);
    const double ny0 = texelNdc(ty * n, t.downsample, t.screenHeight, t.guardY, t.gbufferHeight);
    const double ny1 = texelNdc(std::min(ty * n + n - 1, t.targetHeight - 1), t.downsample, t.screenHeight, t.guardY,
                                t.gbufferHeight);
    int open = -1;  // first tile of the run being built
    auto close = [&](int txEnd) {  // tiles open .. txEnd - 1
      if (open < 0) return;
      current.push_back({std::max(rect.x0, open * n), y0, std::min(rect.x1, txEnd * n - 1), y1});
      open = -1;
    };
    for (int tx = rect.x0 / n; tx <= rect.x1 / n && tx < tiles.tilesX; ++tx) {
      const std::size_t at = 2 * (static_cast<std::size_t>(ty) * tiles.tilesX + tx);
      const double zNear = tiles.zRange[at], zFar = tiles.zRange[at + 1];
      bool keep = zNear >= zFar;
      if (keep) {
        const double nx0 = texelNdc(tx * n, t.downsample, t.screenWidth, t.guardX, t.gbufferWidth);
        const double nx1 = texelNdc(std::min(tx * n + n - 1, t.targetWidth - 1), t.downsample, t.screenWidth,
                                    t.guardX, t.gbufferWidth);
        glm::dvec3 lo(1e300), hi(-1e300);
        for (int k = 0; k < 8; ++k) {
          const glm::dvec3 q = unproject(t, (k & 1) ? nx1 : nx0, (k & 2) ? ny1 : ny0, (k & 4) ? zFar : zNear);
          lo = glm::min(lo, q);
          hi = glm::max(hi, q);
        }
        const glm::dvec3 slack = 1e-4 * (glm::abs(lo) + glm::abs(hi)) + 1e-6;  // float G-buffer depths
        const glm::dvec3 d = c - glm::clamp(c, lo - slack, hi + slack);
        keep = glm::dot(d, d) <= r * r;
      }
      if (keep && open < 0) open = tx;
      if (!keep) close(tx);
    }
    close(std::min(rect.x1 / n, tiles.tilesX - 1) + 1);
    // Rows whose runs match the previous row's extend them.
    if (current.size() == previous.size() &&
        std::equal(current.begin(), current.end(), previous.begin(),
                   [](const TexelRect& a, const TexelRect& b) { return a.x0 == b.x0 && a.x1 == b.x1; })) {
      for (std::size_t i = 0; i < current.size(); ++i) previous[i].y1 = current[i].y1;
    } else {
      flush(previous);
      previous = current;
    }
  }
  flush(previous);
  return runs;
}

}  // namespace aokit
