#include "screen/ObscuranceSettings.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "screen/ObscuranceWarp.h"
#include "screen/PoissonDiscSet.h"

namespace aokit {

const Schema<ObscuranceSettings>& obscuranceSchema() {
  static const Schema<ObscuranceSettings> schema = [] {
    using S = ObscuranceSettings;
    Schema<S> t("obscurance");
    includeDeferred(t, {{AOScale::Full, AOScale::Half, AOScale::Quarter},
                        {DebugView::Off, DebugView::AO, DebugView::Normals, DebugView::Depth}});
    t.integer("samples", &S::samples, 1, 64, "rays per pixel");
    t.integer("m", &S::pointsPerRay, 1, 4, "containment tests along each ray");
    t.choice("interleave", &S::interleave,
             {{"shifts", Interleave::Shifts}, {"rotations", Interleave::Rotations}, {"off", Interleave::Off}},
             "16 sets over a 4x4 pixel pattern: toroidal shifts, the seed's rotations, or one set");
    t.flag("filter", &S::filter, "4x4 depth-aware box filter over the interleave pattern");
    t.flag("silhouette", &S::silhouetteElimination, "silhouette elimination (0 < z - z* < thickness)");
    t.number("thickness", &S::thickness, Interval::aboveZero(4), "silhouette-elimination window, fraction of R");
    t.flag("transfer", &S::ambientTransfer, "ambient transfer W of eq. 9 instead of obscurance");
    t.number("bias", &S::bias, Interval::closed(0, 0.5), "depth bias of the containment test, fraction of R");
    t.number("guard", &S::guard, Interval::closed(0, 0.5), "guard band, fraction of the screen on each side");
    return t;
  }();
  return schema;
}

void validate(const ObscuranceSettings& s) { obscuranceSchema().validate(s); }

std::string ObscuranceConstants::defines() const {
  std::ostringstream d;
  d << "#define OBS_SAMPLES " << samples << "\n"
    << "#define OBS_POINTS_PER_RAY " << pointsPerRay << "\n"
    << "#define OBS_DOWNSAMPLE " << downsample << "\n"
    << "#define OBS_INTERLEAVED " << int(interleaved) << "\n"
    << "#define OBS_FILTER " << int(filter) << "\n"
    << "#define OBS_SILHOUETTE " << int(silhouette) << "\n"
    << "#define OBS_TRANSFER " << int(transfer) << "\n";
  return d.str();
}

ObscuranceConstants makeObscuranceConstants(const ObscuranceSettings& s, const FrameContext& frame) {
  validate(s);
  const double R = frame.radius;
  if (!std::isfinite(R) || !(R > 0.0))
    throw std::invalid_argument("obscurance: the AO radius must be positive: set it or give the scene one");
  ObscuranceConstants c;
  c.samples = s.samples;
  c.pointsPerRay = s.pointsPerRay;
  c.downsample = static_cast<int>(s.common.scale);
  c.interleaved = s.interleave != Interleave::Off;
  c.filter = s.filter;
  c.silhouette = s.silhouetteElimination;
  c.transfer = s.ambientTransfer;
  c.radius = static_cast<float>(R);
  c.bias = static_cast<float>(s.bias * R);
  c.thickness = static_cast<float>(s.thickness * R);
  c.filterTolerance = static_cast<float>(s.common.upsample.depthTolerance);
  c.falloff = frame.falloff;
  const std::vector<glm::dvec3>& unitCube = cachedPoissonDisc(s.samples);
  const int sets = c.interleaved ? kInterleaveCells : 1;
  c.offsets.resize(static_cast<std::size_t>(sets) * s.samples);
  for (int cell = 0; cell < sets; ++cell) {
    const glm::dvec3 shift = interleaveShift(interleaveIndex(cell % kInterleaveSide, cell / kInterleaveSide),
                                             s.interleave);
    for (int i = 0; i < s.samples; ++i) {
      const glm::dvec3 xi = glm::fract(unitCube[i] + shift);  // toroidal: still a Poisson-disc set
      c.offsets[static_cast<std::size_t>(cell) * s.samples + i] = glm::vec3(warpObscuranceSample(xi, c.falloff));
    }
  }
  return c;
}

}  // namespace aokit
