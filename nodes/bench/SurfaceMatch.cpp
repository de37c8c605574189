#include "bench/SurfaceMatch.h"

#include <cmath>
#include <limits>

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>

namespace aokit {

FrameCamera frameCamera(vtkRenderer* renderer, int width, int height) {
  vtkCamera* cam = renderer->GetActiveCamera();
  vtkMatrix4x4* m = cam->GetCompositeProjectionTransformMatrix(double(width) / height, -1, 1);
  FrameCamera fc;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) fc.worldToClip[c][r] = m->GetElement(r, c);  // glm is column-major
  double p[3];
  cam->GetPosition(p);
  fc.eye = {p[0], p[1], p[2]};
  fc.pixelAngle = cam->GetViewAngle() * M_PI / 180.0 / height;
  return fc;
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> matchSurfaces(const SurfaceSamples& a, const FrameCamera& camA,
                                                                   const SurfaceSamples& b) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  for (std::size_t i = 0; i < b.pixelCount(); ++i) {
    if (!b.covered[i]) continue;
    const glm::dvec3 p(b.position[i]);
    const glm::dvec4 clip = camA.worldToClip * glm::dvec4(p, 1.0);
    if (clip.w <= 0.0) continue;
    const double x = (clip.x / clip.w * 0.5 + 0.5) * a.width - 0.5;
    const double y = (clip.y / clip.w * 0.5 + 0.5) * a.height - 0.5;
    const long xi = std::lround(x), yi = std::lround(y);
    if (xi < 0 || yi < 0 || xi >= a.width || yi >= a.height) continue;
    const std::size_t j = a.index(static_cast<int>(xi), static_cast<int>(yi));
    if (!a.covered[j]) continue;
    // One pixel footprint at that distance (nearest-pixel lookup is off by up to half of one).
    const double footprint = glm::distance(p, camA.eye) * camA.pixelAngle;
    if (glm::distance(glm::dvec3(a.position[j]), p) <= footprint)
      pairs.emplace_back(static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j));
  }
  return pairs;
}

double meanChange(const AOBuffer& a, const AOBuffer& b, const std::vector<std::pair<std::uint32_t, std::uint32_t>>& pairs) {
  if (pairs.empty()) return std::numeric_limits<double>::quiet_NaN();
  double sum = 0.0;
  for (const auto& [i, j] : pairs) sum += std::abs(double(b.ao[i]) - double(a.ao[j]));
  return sum / static_cast<double>(pairs.size());
}

}  // namespace aokit
