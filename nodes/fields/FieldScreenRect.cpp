#include "fields/FieldScreenRect.h"

#include <algorithm>
#include <cmath>

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

}  // namespace aokit
