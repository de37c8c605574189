#pragma once
// Per-pixel buffers exchanged between the rasterizer, the reference and the metrics.
// Layout everywhere: row-major, bottom row first (as glReadPixels), index = y * width + x.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace aokit {

// The G-buffer the AO is evaluated on: world-space surface points and unit normals (the normal
// the renderer shades with, facing the camera). Pixels with covered == 0 hold no surface; covered
// pixels with receives == 0 show a prop that receives no AO (its AO is 0 by definition).
struct SurfaceSamples {
  int width = 0, height = 0;
  std::vector<glm::vec3> position, normal;
  std::vector<std::uint8_t> covered, receives;

  std::size_t pixelCount() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
  // Sizes every vector for w x h, all pixels uncovered (and receiving, once covered).
  void resize(int w, int h);
  // Throws std::invalid_argument when a size is negative or a vector does not hold width * height.
  void validate() const;
};

// Ambient occlusion per pixel: ao in [0, 1], 1 = fully occluded. standardError is optional
// (empty, or one value per pixel): the estimator's standard error, filled by the reference.
struct AOBuffer {
  int width = 0, height = 0;
  std::vector<float> ao;
  std::vector<std::uint8_t> covered;
  std::vector<float> standardError;

  std::size_t pixelCount() const { return static_cast<std::size_t>(width) * static_cast<std::size_t>(height); }
  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * width + x; }
  // Sizes ao and covered (and standardError when withError) for w x h: ao 0, nothing covered.
  void resize(int w, int h, bool withError = false);
  // Throws std::invalid_argument on negative sizes or vectors of the wrong length.
  void validate() const;
};

}  // namespace aokit
