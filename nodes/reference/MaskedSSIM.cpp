#include "reference/MaskedSSIM.h"

#include <array>
#include <cmath>
#include <cstddef>

namespace aokit {

namespace {

constexpr int kRadius = 5;  // 11 taps
constexpr int kChannels = 6;  // m, m a, m b, m a^2, m b^2, m a b

std::array<double, 2 * kRadius + 1> gaussianTaps() {
  std::array<double, 2 * kRadius + 1> w{};
  for (int i = -kRadius; i <= kRadius; ++i) w[i + kRadius] = std::exp(-(i * i) / (2.0 * 1.5 * 1.5));
  return w;  // unnormalized: every window divides by its own weight sum
}

}  // namespace

double maskedSSIM(const std::vector<float>& a, const std::vector<float>& b, const std::vector<std::uint8_t>& mask,
                  int width, int height) {
  const double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03;
  const auto taps = gaussianTaps();
  const std::size_t n = static_cast<std::size_t>(width) * height;

  // Horizontal pass of the separable Gaussian over the six masked moments.
  std::vector<std::array<double, kChannels>> h(n);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::array<double, kChannels> s{};
      for (int k = -kRadius; k <= kRadius; ++k) {
        const int xx = x + k;
        if (xx < 0 || xx >= width) continue;
        const std::size_t j = static_cast<std::size_t>(y) * width + xx;
        if (!mask[j]) continue;
        const double w = taps[k + kRadius], va = a[j], vb = b[j];
        s[0] += w;
        s[1] += w * va;
        s[2] += w * vb;
        s[3] += w * va * va;
        s[4] += w * vb * vb;
        s[5] += w * va * vb;
      }
      h[static_cast<std::size_t>(y) * width + x] = s;
    }

  // Vertical pass, evaluated only at masked centres.
  double sum = 0.0;
  std::size_t count = 0;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (!mask[static_cast<std::size_t>(y) * width + x]) continue;
      std::array<double, kChannels> s{};
      for (int k = -kRadius; k <= kRadius; ++k) {
        const int yy = y + k;
        if (yy < 0 || yy >= height) continue;
        const auto& r = h[static_cast<std::size_t>(yy) * width + x];
        for (int c = 0; c < kChannels; ++c) s[c] += taps[k + kRadius] * r[c];
      }
      const double W = s[0];  // > 0: the centre itself is masked
      const double ma = s[1] / W, mb = s[2] / W;
      const double va = s[3] / W - ma * ma, vb = s[4] / W - mb * mb, cov = s[5] / W - ma * mb;
      sum += ((2 * ma * mb + C1) * (2 * cov + C2)) / ((ma * ma + mb * mb + C1) * (va + vb + C2));
      ++count;
    }
  return count ? sum / count : 1.0;
}

}  // namespace aokit
