#include "fields/RadialFieldEval.h"

#include <algorithm>
#include <cmath>

#include "fields/CapIntegralTable.h"
#include "fields/CubeMapLayout.h"
#include "fields/HorizonLimit.h"
#include "fields/SphericalCaps.h"
#include "fields/TextureSampling.h"

namespace aokit {

double glslSmoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

void fetchRadialTexels(const RadialField& field, const glm::dvec3& direction, float occlusion[4], float centroid[3]) {
  const FaceCoordinates f = directionToFace(direction);
  const int side = field.layerSide(), n = field.resolution;
  const std::size_t layer = static_cast<std::size_t>(f.face) * side * side;
  const double x = borderedFilterCoordinate(f.u, n), y = borderedFilterCoordinate(f.v, n);
  sampleLinear2D(field.occlusion.data() + layer * 4, side, side, 4, x, y, occlusion);
  sampleLinear2D(field.centroid.data() + layer * 3, side, side, 3, x, y, centroid);
}

RadialSample evaluateRadialField(const RadialField& field, const glm::dvec3& x, const glm::dvec3& n,
                                 const FieldEvalSettings& options) {
  RadialSample s;
  const double r = glm::length(x);
  if (!(r <= field.rMax)) return s;  // also NaN
  const glm::dvec3 w = r > 0.0 ? x / r : glm::dvec3(0.0, 0.0, 1.0);
  float occ[4], c0[3];
  fetchRadialTexels(field, w, occ, c0);
  const double a = occ[0], b = occ[1], c = occ[2], r0 = occ[3];
  const double rc = std::max(r, r0);
  const double denom = (a * rc + b) * rc + c;
  s.solidAngle = denom > 0.0 ? std::clamp(1.0 / denom, 0.0, kFourPi) : kFourPi;
  const glm::dvec3 toCentre = glm::dvec3(c0[0], c0[1], c0[2]) - rc * w;
  const double len = glm::length(toCentre);
  s.direction = len > 0.0 ? toCentre / len : -w;
  s.capOcclusion = capIntegralTable().sample(s.solidAngle, glm::dot(n, s.direction));
  double ao = s.capOcclusion;
  if (r < r0) {
    const double t = std::pow(r / r0, options.insideExponent);
    ao = t * ao + (1.0 - t) * options.insideOcclusion;
  }
  s.occlusion = ao * field.fade(r, r0) * horizonLimit(field, x, n, s.solidAngle, glm::dot(n, s.direction));
  return s;
}

RadialSample evaluateRadialField(const RadialField& field, const glm::dmat4& occluderToWorld, const glm::dvec3& p,
                                 const glm::dvec3& n, const FieldEvalSettings& options) {
  const glm::dmat4 inv = glm::inverse(occluderToWorld);
  const glm::dvec3 x = glm::dvec3(inv * glm::dvec4(p, 1.0)) - field.centre;
  const glm::dvec3 nf = glm::normalize(glm::transpose(glm::dmat3(occluderToWorld)) * n);  // N(O^-1) = O^T
  RadialSample s = evaluateRadialField(field, x, nf, options);
  const glm::dvec3 d = glm::dmat3(occluderToWorld) * s.direction;  // a direction: the linear part of O
  const double len = glm::length(d);
  if (len > 0.0) s.direction = d / len;
  return s;
}

}  // namespace aokit
