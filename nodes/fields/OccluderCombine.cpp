#include "fields/OccluderCombine.h"

#include <algorithm>
#include <cmath>

#include "fields/ConeTables.h"
#include "fields/SphericalCaps.h"

namespace aokit {

double combineMultiply(const std::vector<double>& occlusions) {
  double open = 1.0;
  for (double a : occlusions) open *= 1.0 - std::clamp(a, 0.0, 1.0);
  return 1.0 - open;
}

namespace {
// The cap around n whose occlusion is a: sin^2(alpha) = a.
OcclusionCone capAroundNormal(double a, const glm::dvec3& n) {
  return {a, 2.0 * kPi * (1.0 - std::sqrt(std::max(0.0, 1.0 - a))), n};
}
}  // namespace

OcclusionCone clipOccluderCone(const OccluderSample& s, const glm::dvec3& n) {
  const double a = std::clamp(s.occlusion, 0.0, 1.0);
  if (!(a > 0.0)) return {0.0, 0.0, n};
  const double cosBeta = glm::dot(s.direction, n);
  const ClippedCone clipped = clipTable().sample(s.solidAngle, cosBeta);
  const glm::dvec3 mixed = (1.0 - clipped.lerp) * s.direction + clipped.lerp * n;
  const double len = glm::length(mixed);
  const glm::dvec3 d = len > 1e-12 ? mixed / len : n;
  if (!(s.capOcclusion > 1e-6) || !(clipped.solidAngle > 0.0)) return capAroundNormal(a, n);
  return {a, std::min(2.0 * kPi, clipped.solidAngle * a / s.capOcclusion), d};
}

OcclusionCone mergeOcclusionCones(const OcclusionCone& a, const OcclusionCone& b) {
  if (!(a.solidAngle > 0.0)) return {std::min(1.0, a.occlusion + b.occlusion), b.solidAngle, b.direction};
  if (!(b.solidAngle > 0.0)) return {std::min(1.0, a.occlusion + b.occlusion), a.solidAngle, a.direction};
  const double sum = a.solidAngle + b.solidAngle;
  const double uni = std::clamp(mergeTable().sample(a.solidAngle, b.solidAngle, glm::dot(a.direction, b.direction)),
                                std::max(a.solidAngle, b.solidAngle), std::min(sum, 2.0 * kPi));
  OcclusionCone out;
  out.solidAngle = uni;
  out.occlusion = std::clamp((a.occlusion + b.occlusion) * uni / sum, std::max(a.occlusion, b.occlusion),
                             std::min(1.0, a.occlusion + b.occlusion));
  const glm::dvec3 d = a.solidAngle * a.direction + b.solidAngle * b.direction;
  const double len = glm::length(d);
  out.direction = len > 1e-12 ? d / len : a.direction;
  return out;
}

double combineCones(const std::vector<OccluderSample>& samples, const glm::dvec3& n) {
  OcclusionCone acc{0.0, 0.0, n};
  for (const auto& s : samples) acc = mergeOcclusionCones(acc, clipOccluderCone(s, n));
  return std::clamp(acc.occlusion, 0.0, 1.0);
}

}  // namespace aokit
