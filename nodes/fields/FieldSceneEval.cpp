#include "fields/FieldSceneEval.h"

#include <stdexcept>

#include "fields/GridFieldEval.h"
#include "fields/RadialFieldEval.h"

namespace aokit {

OccluderSample evaluateOccluder(const BakedField& field, const glm::dmat4& occluderToWorld, const glm::dvec3& p,
                                const glm::dvec3& n, const FieldEvalSettings& s) {
  OccluderSample out;
  if (field.info.kind == FieldKind::Cube) {
    const RadialSample r = evaluateRadialField(field.radial, occluderToWorld, p, n, s);
    out.occlusion = r.occlusion;
    out.solidAngle = r.solidAngle;
    out.direction = r.direction;
    out.capOcclusion = r.capOcclusion;
  } else {
    out.occlusion = evaluateGridField(field.grid, occluderToWorld, glm::dmat4(1.0), p, n, s);
    out.direction = n;  // no cap: clipOccluderCone makes it the cap around n of its occlusion
  }
  return out;
}

bool ownPixel(const FieldOccluder& o, std::uint32_t pixelId, const glm::dvec3& p) {
  if (o.instanceId == 0 || o.instanceId != pixelId) return false;
  if (!o.ownBox.valid()) return true;
  return glm::all(glm::greaterThanEqual(p, o.ownBox.min)) && glm::all(glm::lessThanEqual(p, o.ownBox.max));
}

double evaluateFieldScene(const std::vector<std::shared_ptr<const BakedField>>& fields,
                          const std::vector<FieldOccluder>& occluders, const glm::dvec3& p, const glm::dvec3& n,
                          std::uint32_t pixelId, const FieldEvalSettings& s) {
  std::vector<OccluderSample> samples;
  std::vector<double> occlusions;
  for (const FieldOccluder& o : occluders)
    if (o.field < 0 || o.field >= static_cast<int>(fields.size()) || !fields[o.field])
      throw std::invalid_argument("field scene: occluder names a missing field");
  for (int pass = 0; pass < 2; ++pass)  // cube fields first
    for (const FieldOccluder& o : occluders) {
      const BakedField& f = *fields[o.field];
      if ((f.info.kind == FieldKind::Cube) != (pass == 0)) continue;
      if (ownPixel(o, pixelId, p)) continue;
      const OccluderSample k = evaluateOccluder(f, o.occluderToWorld, p, n, s);
      samples.push_back(k);
      occlusions.push_back(k.occlusion);
    }
  return s.combine == FieldCombine::Cone ? combineCones(samples, n) : combineMultiply(occlusions);
}

}  // namespace aokit
