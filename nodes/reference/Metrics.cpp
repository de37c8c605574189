#include "reference/Metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "reference/MaskedSSIM.h"

namespace aokit {

namespace {

const char* kNoPixels = "no covered pixels to compare";

void requireSameSize(const AOBuffer& a, const AOBuffer& b) {
  a.validate();
  b.validate();
  if (a.width != b.width || a.height != b.height)
    throw std::invalid_argument("AO buffers differ in size: " + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + " vs " + std::to_string(b.width) + "x" +
                                std::to_string(b.height));
}

}  // namespace

AOErrorMetrics compareAO(const AOBuffer& test, const AOBuffer& reference) {
  requireSameSize(test, reference);
  const std::size_t n = test.pixelCount();
  std::vector<std::uint8_t> both(n);
  std::vector<double> absErr;
  double sumSq = 0.0, sumAbs = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    both[i] = test.covered[i] && reference.covered[i];
    if (!both[i]) continue;
    const double e = std::abs(static_cast<double>(test.ao[i]) - reference.ao[i]);
    absErr.push_back(e);
    sumSq += e * e;
    sumAbs += e;
  }
  if (absErr.empty()) throw std::invalid_argument(kNoPixels);

  AOErrorMetrics m;
  m.pixels = absErr.size();
  m.rmse = std::sqrt(sumSq / m.pixels);
  m.meanAbsError = sumAbs / m.pixels;
  const std::size_t rank = static_cast<std::size_t>(std::ceil(0.99 * m.pixels));  // 1-based, >= 1
  std::nth_element(absErr.begin(), absErr.begin() + (rank - 1), absErr.end());
  m.p99AbsError = absErr[rank - 1];
  std::vector<float> a(n), b(n);
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = 1.0f - test.ao[i];
    b[i] = 1.0f - reference.ao[i];
  }
  m.ssim = maskedSSIM(a, b, both, test.width, test.height);
  return m;
}

double temporalChange(const std::vector<AOBuffer>& frames, const std::vector<std::uint8_t>& staticMask) {
  if (frames.size() < 2) throw std::invalid_argument("temporalChange needs at least two frames");
  for (std::size_t f = 1; f < frames.size(); ++f) requireSameSize(frames[f], frames[0]);
  const std::size_t n = frames[0].pixelCount();
  if (!staticMask.empty() && staticMask.size() != n)
    throw std::invalid_argument("static mask holds " + std::to_string(staticMask.size()) + " values for " +
                                std::to_string(n) + " pixels");
  double sumOfMeans = 0.0;
  std::size_t pairs = 0;
  for (std::size_t f = 1; f < frames.size(); ++f) {
    const AOBuffer &a = frames[f - 1], &b = frames[f];
    double sum = 0.0;
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!a.covered[i] || !b.covered[i] || (!staticMask.empty() && !staticMask[i])) continue;
      sum += std::abs(static_cast<double>(b.ao[i]) - a.ao[i]);
      ++count;
    }
    if (count == 0) continue;  // e.g. the object left the view for a frame: the pair says nothing
    sumOfMeans += sum / count;
    ++pairs;
  }
  if (pairs == 0) throw std::invalid_argument(kNoPixels);
  return sumOfMeans / pairs;
}

double meanStandardError(const AOBuffer& buffer) {
  buffer.validate();
  if (buffer.standardError.empty()) throw std::invalid_argument("AO buffer has no standard error");
  double sumSq = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < buffer.pixelCount(); ++i) {
    if (!buffer.covered[i]) continue;
    sumSq += static_cast<double>(buffer.standardError[i]) * buffer.standardError[i];
    ++count;
  }
  if (count == 0) throw std::invalid_argument(kNoPixels);
  return std::sqrt(sumSq / count);
}

}  // namespace aokit
