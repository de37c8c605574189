#include "reference/Falloff.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

namespace aokit {

double falloffWeight(Falloff f, double d, double R) {
  if (!(R > 0.0) || !std::isfinite(R)) throw std::invalid_argument("falloffWeight: radius must be positive and finite");
  if (!(d < R)) return 0.0;  // also catches NaN distances: no occlusion
  const double q = std::max(d, 0.0) / R;
  switch (f) {
    case Falloff::Binary:
      return 1.0;
    case Falloff::Wendland: {
      const double s = 1.0 - q;
      return (s * s) * (s * s) * (4.0 * q + 1.0);
    }
    case Falloff::Sqrt:
      return 1.0 - std::sqrt(q);
    case Falloff::Exponential: {
      static const double e3 = std::exp(-3.0);
      return (std::exp(-3.0 * q) - e3) / (1.0 - e3);
    }
  }
  throw std::invalid_argument("falloffWeight: unknown falloff value");
}

std::string falloffName(Falloff f) {
  switch (f) {
    case Falloff::Binary: return "binary";
    case Falloff::Wendland: return "wendland";
    case Falloff::Sqrt: return "sqrt";
    case Falloff::Exponential: return "exponential";
  }
  throw std::invalid_argument("falloffName: unknown falloff value");
}

Falloff parseFalloff(const std::string& name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  std::string valid;
  for (Falloff f : kAllFalloffs) {
    if (lower == falloffName(f)) return f;
    valid += (valid.empty() ? "" : ", ") + falloffName(f);
  }
  throw std::invalid_argument("unknown falloff '" + name + "' (valid: " + valid + ")");
}

}  // namespace aokit
