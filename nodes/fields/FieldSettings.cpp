#include "fields/FieldSettings.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace aokit {

namespace {
[[noreturn]] void fail(const std::string& field, const std::string& rule, double got) {
  std::ostringstream msg;
  msg << "field: " << field << " must be " << rule << ", got " << got;
  throw std::invalid_argument(msg.str());
}
bool in(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }
}  // namespace

int maxFieldResolution(FieldKind) { return 128; }

void validate(const FieldSettings& s) {
  const int maxRes = maxFieldResolution(s.kind);
  if (s.resolution != 0 && (s.resolution < 2 || s.resolution > maxRes))
    fail("resolution", "0 (auto) or in 2.." + std::to_string(maxRes) + " for kind " + fieldKindName(s.kind),
         s.resolution);
  if (s.combine == FieldCombine::Cone && s.kind != FieldKind::Cube)
    throw std::invalid_argument("field: combine=cone needs kind=cube (grids store no cone)");
  if (!in(s.radius, 0.0, 1e30)) fail("radius", ">= 0 (0 = the scene's AO radius)", s.radius);
  if (!in(s.farDistance, 0.0, 4.0)) fail("farDistance", "0 (auto) or in (0, 4] (a fraction of R)", s.farDistance);
  if (s.farDistance > 0.0 && (!in(s.nearDistance, 0.0, 4.0) || s.nearDistance >= s.farDistance))
    fail("nearDistance", "in [0, farDistance) (a fraction of R)", s.nearDistance);
  if (!in(s.insideExponent, 0.0, 16.0) || s.insideExponent <= 0.0) fail("insideExponent", "in (0, 16]", s.insideExponent);
  if (!in(s.insideOcclusion, 0.0, 1.0)) fail("insideOcclusion", "in [0, 1]", s.insideOcclusion);
  if (s.supersampling != 1 && s.supersampling != 2) fail("supersampling", "1 or 2", s.supersampling);
  if (s.radialSamples < 4 || s.radialSamples > 64) fail("radialSamples", "in 4..64", s.radialSamples);
  if (s.raysPerSample < 8 || s.raysPerSample > 4096) fail("raysPerSample", "in 8..4096", s.raysPerSample);
  if (s.gridRays < 8 || s.gridRays > 4096) fail("gridRays", "in 8..4096", s.gridRays);
  if (!in(s.fadeCells, 0.0, 8.0)) fail("fadeCells", "in [0, 8] (grid cells)", s.fadeCells);
  if (!in(s.padding, 0.0, 4.0)) fail("padding", "in [0, 4] (a fraction of R)", s.padding);
  if (!in(s.bias, 0.0, 4.0)) fail("bias", "in [0, 4] (grid cells)", s.bias);
  if (s.selfOcclusionRays < 1 || s.selfOcclusionRays > 65536)
    fail("selfOcclusionRays", "in 1..65536", s.selfOcclusionRays);
  if (s.threads < 0 || s.threads > 1024) fail("threads", "in 0..1024 (0 = all cores)", s.threads);
}

std::string fieldKindName(FieldKind k) {
  switch (k) {
    case FieldKind::Cube: return "cube";
    case FieldKind::Grid6: return "grid6";
    case FieldKind::Grid4: return "grid4";
  }
  throw std::invalid_argument("fieldKindName: unknown kind");
}

FieldKind parseFieldKind(const std::string& name) {
  for (FieldKind k : {FieldKind::Cube, FieldKind::Grid6, FieldKind::Grid4})
    if (name == fieldKindName(k)) return k;
  throw std::invalid_argument("unknown field kind '" + name + "' (valid: cube, grid6, grid4)");
}

std::string fieldCombineName(FieldCombine c) { return c == FieldCombine::Cone ? "cone" : "multiply"; }

FieldCombine parseFieldCombine(const std::string& name) {
  if (name == "multiply") return FieldCombine::Multiply;
  if (name == "cone") return FieldCombine::Cone;
  throw std::invalid_argument("unknown field combine '" + name + "' (valid: multiply, cone)");
}

}  // namespace aokit

namespace aokit {

std::string gridWeightsName(GridWeights w) { return w == GridWeights::Seed ? "seed" : "normalized"; }

GridWeights parseGridWeights(const std::string& name) {
  if (name == "seed") return GridWeights::Seed;
  if (name == "normalized") return GridWeights::Normalized;
  throw std::invalid_argument("unknown grid weights '" + name + "' (valid: seed, normalized)");
}

}  // namespace aokit
