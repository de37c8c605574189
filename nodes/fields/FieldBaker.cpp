#include "fields/FieldBaker.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "fields/FieldResolution.h"
#include "fields/GridFieldBake.h"
#include "fields/RadialFieldBake.h"
#include "fields/SelfOcclusionBake.h"

namespace aokit {

BakedField bakeField(const BakeMesh& input, const FieldBakeSettings& settings, double radius, Falloff falloff,
                     const std::function<void(double)>& progress) {
  validate(settings);
  if (!(radius > 0.0) || !std::isfinite(radius)) throw std::invalid_argument("field bake: radius must be positive and finite");
  const TriangleMesh& mesh = input.mesh();
  const auto start = std::chrono::steady_clock::now();
  FieldBakeSettings s = settings;
  s.resolution = resolveFieldResolution(settings, mesh, radius);

  // Progress: the field takes most of the time; self-occlusion the last part.
  const double fieldShare = s.selfOcclusion ? 0.8 : 1.0;
  auto part = [&](double from, double share) {
    return [&progress, from, share](double f) {
      if (progress) progress(from + share * f);
    };
  };
  BakedField out;
  out.info = makeBakeInfo(s, s.resolution, radius, falloff, input);
  if (s.kind == FieldKind::Cube)
    out.radial = bakeRadialField(input, s, radius, falloff, part(0.0, fieldShare));
  else
    out.grid = bakeGridField(input, s, radius, falloff, part(0.0, fieldShare));
  if (s.selfOcclusion) {
    const int sides = out.info.selfOcclusionBack ? 2 : 1;
    SelfOcclusion self = bakeSelfOcclusion(input, radius, falloff, s.selfOcclusionRays, sides, s.selfRefinements,
                                           s.threads, s.seed, part(fieldShare, 1.0 - fieldShare));
    out.info.selfPointCount = static_cast<std::uint32_t>(self.points.pointCount());
    out.vertexOcclusion = std::move(self.values);
    out.selfPoints = std::make_shared<const CreaseSplit>(std::move(self.points));
  }
  out.info.bakeSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace aokit
