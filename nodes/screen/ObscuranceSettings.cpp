#include "screen/ObscuranceSettings.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "screen/ObscuranceWarp.h"
#include "screen/PoissonDiscSet.h"

namespace aokit {

namespace {
[[noreturn]] void fail(const std::string& field, const std::string& rule, double got) {
  std::ostringstream msg;
  msg << "obscurance: " << field << " must be " << rule << ", got " << got;
  throw std::invalid_argument(msg.str());
}
bool finite(double v) { return std::isfinite(v); }
}  // namespace

void validate(const ObscuranceSettings& s) {
  if (s.samples < 1 || s.samples > 64) fail("samples", "in 1..64", s.samples);
  if (!finite(s.radius) || s.radius < 0.0) fail("radius", ">= 0 (0 = the scene's AO radius)", s.radius);
  if (s.pointsPerRay < 1 || s.pointsPerRay > 4) fail("pointsPerRay", "in 1..4", s.pointsPerRay);
  if (s.resolutionScale != 1.0 && s.resolutionScale != 0.5)
    fail("resolutionScale", "1 (full) or 0.5 (half)", s.resolutionScale);
  if (!finite(s.bias) || s.bias < 0.0 || s.bias > 0.5) fail("bias", "in 0..0.5 (a fraction of R)", s.bias);
  if (!finite(s.thickness) || s.thickness <= 0.0 || s.thickness > 4.0)
    fail("thickness", "in (0, 4] (a fraction of R)", s.thickness);
  if (!finite(s.filterTolerance) || s.filterTolerance <= 0.0 || s.filterTolerance > 1.0)
    fail("filterTolerance", "in (0, 1]", s.filterTolerance);
  if (!finite(s.guard) || s.guard < 0.0 || s.guard > 0.5)
    fail("guard", "in 0..0.5 (a fraction of the screen size on each side)", s.guard);
}

std::string ObscuranceConstants::defines() const {
  std::ostringstream d;
  d << "#define OBS_SAMPLES " << samples << "\n"
    << "#define OBS_POINTS_PER_RAY " << pointsPerRay << "\n"
    << "#define OBS_DOWNSAMPLE " << downsample << "\n"
    << "#define OBS_INTERLEAVED " << int(interleaved) << "\n"
    << "#define OBS_FILTER " << int(filter) << "\n"
    << "#define OBS_SILHOUETTE " << int(silhouette) << "\n"
    << "#define OBS_TRANSFER " << int(transfer) << "\n"
    << "#define OBS_DEBUG_VIEW " << debugView << "\n";
  return d.str();
}

ObscuranceConstants makeObscuranceConstants(const ObscuranceSettings& s, double sceneRadius, Falloff sceneFalloff) {
  validate(s);
  const double R = s.radius > 0.0 ? s.radius : sceneRadius;
  if (!finite(R) || !(R > 0.0)) fail("radius", "positive: set it or give the scene an AO radius", R);
  ObscuranceConstants c;
  c.samples = s.samples;
  c.pointsPerRay = s.pointsPerRay;
  c.downsample = s.resolutionScale == 0.5 ? 2 : 1;
  c.interleaved = s.interleave != Interleave::Off;
  c.filter = s.filter;
  c.silhouette = s.silhouetteElimination;
  c.transfer = s.ambientTransfer;
  c.debugView = static_cast<int>(s.debugView);
  c.radius = static_cast<float>(R);
  c.bias = static_cast<float>(s.bias * R);
  c.thickness = static_cast<float>(s.thickness * R);
  c.filterTolerance = static_cast<float>(s.filterTolerance);
  c.falloff = s.falloff.value_or(sceneFalloff);
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
