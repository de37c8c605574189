#include "fields/GridFieldEval.h"

#include <algorithm>

#include "fields/TextureSampling.h"

namespace aokit {

double evaluateGridField(const GridField& field, const glm::dvec3& p, const glm::dvec3& n,
                         const FieldEvalSettings& options) {
  const int res = field.resolution;
  const glm::dvec3 pf = glm::dvec3(field.fieldFromOccluder() * glm::dvec4(p, 1.0)) + n * (options.bias / res);
  const glm::dvec3 x = pf * static_cast<double>(res) - 0.5;  // filter coordinates
  double a = 0.0, weightSum = 0.0;
  auto weight = [&](double c) {
    c = std::max(0.0, c);
    weightSum += c;
    return c;
  };
  if (field.kind == FieldKind::Grid4) {
    float t[4];
    sampleLinear3D(field.texels.data(), res, res, res, 4, x.x, x.y, x.z, t);
    const auto& d = tetrahedronDirections();
    for (int i = 0; i < 4; ++i) a += t[i] * weight(glm::dot(d[i], n));
  } else {
    float neg[3], pos[3];
    sampleLinear3D(field.texels.data(), res, res, res, 3, x.x, x.y, x.z, neg);
    sampleLinear3D(field.texels.data() + field.pointCount() * 3, res, res, res, 3, x.x, x.y, x.z, pos);
    for (int c = 0; c < 3; ++c) a += neg[c] * weight(-n[c]) + pos[c] * weight(n[c]);
  }
  if (options.gridWeights == GridWeights::Normalized && weightSum > 0.0) a /= weightSum;
  return std::clamp(a, 0.0, 1.0);
}

double evaluateGridField(const GridField& field, const glm::dmat4& occluderToWorld, const glm::dmat4& receiverToWorld,
                         const glm::dvec3& pr, const glm::dvec3& nr, const FieldEvalSettings& options) {
  const glm::dmat4 m = glm::inverse(occluderToWorld) * receiverToWorld;
  const glm::dvec3 p = glm::dvec3(m * glm::dvec4(pr, 1.0));
  const glm::dvec3 n = glm::normalize(glm::transpose(glm::inverse(glm::dmat3(m))) * nr);
  return evaluateGridField(field, p, n, options);
}

}  // namespace aokit
