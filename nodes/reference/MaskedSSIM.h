#pragma once
// SSIM restricted to a pixel mask (Wang, Bovik, Sheikh, Simoncelli 2004, with their constants).
#include <cstdint>
#include <vector>

namespace aokit {

// Mean SSIM over the pixels with mask != 0, for images with values in [0, 1] (C1 = 0.01^2,
// C2 = 0.03^2), using an 11x11 Gaussian window of sigma 1.5. Each window's statistics are weighted
// sums over its masked pixels only, divided by the sum of their weights, so uncovered pixels (and
// pixels beyond the border) neither pull means toward 0 nor add false structure at silhouettes.
// Variances are the weighted population variances, as in the original. Returns 1 for no pixels.
double maskedSSIM(const std::vector<float>& a, const std::vector<float>& b, const std::vector<std::uint8_t>& mask,
                  int width, int height);

}  // namespace aokit
