#include "io/SceneLimits.h"

#include <charconv>
#include <cmath>
#include <sstream>

#include "core/Finite.h"
#include "io/TextNumbers.h"

namespace aokit {
namespace {

std::string shortNumber(double v) {
  if (v >= 1.8e19) return "18446744073709551615";  // the largest 64-bit seed, which a double rounds up
  std::ostringstream s;
  s.precision(15);
  s << v;
  return s.str();
}


}  // namespace

bool NumberRange::contains(double v) const {
  if (!std::isfinite(v) || v > max || v < min || (minExclusive && v == min)) return false;
  return !integer || v == std::floor(v);
}

std::string NumberRange::describe() const {
  const std::string u = *unit ? std::string(" ") + unit : std::string();
  if (minExclusive && min == 0.0) return "a positive number (at most " + shortNumber(max) + u + ")";
  if (minExclusive) return "a number > " + shortNumber(min) + " (at most " + shortNumber(max) + u + ")";
  return std::string(integer ? "an integer" : "a number") + " in [" + shortNumber(min) + ", " + shortNumber(max) +
         "]" + u;
}

std::string NumberRange::problemWith(std::string_view text) const {
  if (integer && max > 9.2e18) {  // the full unsigned 64-bit range: parse as such, not as a double
    std::uint64_t v = 0;
    const bool digits = !text.empty() && text.find_first_not_of("0123456789") == std::string_view::npos;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (digits && ec == std::errc() && end == text.data() + text.size()) return {};
    return "is not " + describe();
  }
  double v = 0.0;
  if (!parseReal(text, v) || !contains(v)) return "is not " + describe();
  return {};
}

std::optional<CameraProblem> cameraProblem(const Camera& c) {
  using P = CameraProblem;
  auto coordinate = [](const glm::dvec3& v) {
    return allFinite(v) && limits::kCoordinate.contains(v.x) && limits::kCoordinate.contains(v.y) &&
           limits::kCoordinate.contains(v.z);
  };
  const std::string coords = "must be 3 numbers in [" + shortNumber(limits::kCoordinate.min) + ", " +
                             shortNumber(limits::kCoordinate.max) + "] " + limits::kCoordinate.unit;
  if (!coordinate(c.position)) return P{P::Position, coords};
  if (!coordinate(c.focalPoint)) return P{P::FocalPoint, coords};
  if (!allFinite(c.viewUp)) return P{P::ViewUp, "must be 3 finite numbers"};
  if (!limits::kViewAngle.contains(c.viewAngleDeg)) return P{P::ViewAngle, "must be " + limits::kViewAngle.describe()};
  const glm::dvec3 dir = c.focalPoint - c.position;
  if (!(glm::length(dir) > 0.0)) return P{P::FocalPoint, "coincides with the camera position"};
  const double up = glm::length(c.viewUp);
  if (!(up > 0.0)) return P{P::ViewUp, "has zero length"};
  if (glm::length(glm::cross(glm::normalize(dir), c.viewUp / up)) < 1e-6)
    return P{P::ViewUp, "is parallel to the view direction"};
  return std::nullopt;
}

}  // namespace aokit
