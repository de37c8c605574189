#include "fields/FieldPassSettings.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace aokit {

namespace {
[[noreturn]] void fail(const std::string& field, const std::string& rule, double got) {
  std::ostringstream msg;
  msg << "field pass: " << field << " must be " << rule << ", got " << got;
  throw std::invalid_argument(msg.str());
}
bool in(double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; }
}  // namespace

void validate(const FieldPassSettings& s) {
  if (!in(s.insideExponent, 0.0, 16.0) || s.insideExponent <= 0.0) fail("insideExponent", "in (0, 16]", s.insideExponent);
  if (!in(s.insideOcclusion, 0.0, 1.0)) fail("insideOcclusion", "in [0, 1]", s.insideOcclusion);
  if (!in(s.bias, 0.0, 4.0)) fail("bias", "in [0, 4] (grid cells)", s.bias);
  if (s.resolutionScale != 1.0 && s.resolutionScale != 0.5 && s.resolutionScale != 0.25)
    fail("resolutionScale", "1, 0.5 or 0.25", s.resolutionScale);
  if (s.upsampleWindow != 0 && (s.upsampleWindow < 2 || s.upsampleWindow > 32))
    fail("upsampleWindow", "0 or in 2..32 (pixels)", s.upsampleWindow);
  if (!in(s.depthTolerance, 0.0, 1.0) || s.depthTolerance <= 0.0) fail("depthTolerance", "in (0, 1]", s.depthTolerance);
  if (s.sliceAxis < 0 || s.sliceAxis > 2) fail("sliceAxis", "0, 1 or 2 (x, y, z)", s.sliceAxis);
  if (!in(s.slicePosition, -1e30, 1e30)) fail("slicePosition", "finite", s.slicePosition);
}

FieldPassSettings passSettingsFrom(const FieldSettings& s) {
  FieldPassSettings p;
  p.combine = s.combine;
  p.insideExponent = s.insideExponent;
  p.insideOcclusion = s.insideOcclusion;
  p.bias = s.bias;
  p.gridWeights = s.gridWeights;
  return p;
}

std::string fieldDebugViewName(FieldDebugView v) {
  switch (v) {
    case FieldDebugView::None: return "none";
    case FieldDebugView::AO: return "ao";
    case FieldDebugView::Normals: return "normals";
    case FieldDebugView::Depth: return "depth";
    case FieldDebugView::Count: return "count";
    case FieldDebugView::Slice: return "slice";
  }
  return "none";
}

}  // namespace aokit
