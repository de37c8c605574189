#pragma once
// Image metrics between an AO buffer under test and the reference, over covered pixels only.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "reference/SurfaceSamples.h"

namespace aokit {

struct AOErrorMetrics {
  double rmse = 0.0;
  double meanAbsError = 0.0;
  // 99th percentile of |test - reference|, nearest-rank: the ceil(0.99 n)-th smallest of the n
  // absolute errors (an actual error value, never interpolated).
  double p99AbsError = 0.0;
  // Mean SSIM (Wang et al. 2004: C1 = 0.01^2, C2 = 0.03^2 for data range 1, 11x11 Gaussian window
  // with sigma 1.5) over the compared pixels, on visible intensity 1 - AO (what a viewer sees; on
  // occlusion itself, the near-zero means of open floors made tiny biases dominate the luminance term). Masked: a window's means, variances and covariance
  // use only its pixels covered in both buffers, with the Gaussian weights renormalized over them;
  // pixels outside the image count as uncovered.
  double ssim = 0.0;
  std::size_t pixels = 0;  // pixels covered in both buffers
};

// Throws std::invalid_argument when the buffers differ in size or are malformed, and
// "no covered pixels to compare" when no pixel is covered in both.
AOErrorMetrics compareAO(const AOBuffer& test, const AOBuffer& reference);

// Flicker: for each consecutive pair of frames, the mean |AO_t - AO_{t-1}| over pixels covered in
// both and marked static (staticMask != 0; an empty mask means every pixel is static); then the
// mean over the pairs that have such pixels. Needs at least two frames of one size. Throws
// std::invalid_argument on a size mismatch and when no pair has a pixel to compare.
double temporalChange(const std::vector<AOBuffer>& frames, const std::vector<std::uint8_t>& staticMask);

// RMS of the per-pixel standard error over covered pixels: the reference's own noise level.
// Throws std::invalid_argument when the buffer has no standard error or no covered pixel.
double meanStandardError(const AOBuffer& buffer);

}  // namespace aokit
