#pragma once
// Which AO-target texels an occluder's influence sphere can reach (pure CPU, tested without GL):
// the field pass scissors each occluder's draw to this rectangle.
//
// The sphere's view-space bounding box is projected corner by corner (the projection of a convex
// box contains that of the sphere inside it). A corner at or behind the eye plane (clip w <= 0,
// perspective) makes the rectangle the whole target; all eight behind it, or a rectangle off the
// screen, make it empty. Pixel g of the G-buffer sits at NDC (g + 0.5) / size * 2 - 1
// (DeferredCommon.glsl) and AO-target texel c stands for G-buffer texel min(c ds, screen - 1) +
// guard; the texel range is widened by one on each side against rounding.
#include <vector>

#include <glm/glm.hpp>

namespace aokit {

struct TexelRect {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // inclusive; empty when x1 < x0 or y1 < y0
  bool empty() const { return x1 < x0 || y1 < y0; }
  long long area() const { return empty() ? 0 : static_cast<long long>(x1 - x0 + 1) * (y1 - y0 + 1); }
};

struct TargetGeometry {
  float clip[3][4] = {};        // rows 0, 1 and 3 of the G-buffer's view -> clip matrix
  int gbufferWidth = 0, gbufferHeight = 0, guardX = 0, guardY = 0;
  int screenWidth = 0, screenHeight = 0;
  int downsample = 1, targetWidth = 0, targetHeight = 0;
};

TexelRect sphereTexelRect(const glm::dvec3& centreView, double radius, const TargetGeometry& t);

// Depth ranges of what was drawn (a bound on the receivers) per tile of the AO target
// (FieldPassBoundsFS.glsl), read back once a frame: zRange[2 (ty tilesX + tx)] = nearest view z,
// [+1] = farthest (nearest < farthest: none).
struct TileDepths {
  int tile = 16;  // tile side, AO-target texels
  int tilesX = 0, tilesY = 0;
  std::vector<float> zRange;
};

// The part of sphereTexelRect that holds receivers the sphere can reach, as scissor rectangles:
// tiles whose receivers' view-space box (the frustum slice through the tile's outermost pixel
// centres between its nearest and farthest receiver) misses the sphere are dropped, the rest
// merged into runs along rows and then rows with equal runs. Every receiver of a kept tile lies in
// that box, so a dropped tile holds no receiver within the sphere.
std::vector<TexelRect> sphereTexelRuns(const glm::dvec3& centreView, double radius, const TargetGeometry& t,
                                       const TileDepths& tiles);

}  // namespace aokit
