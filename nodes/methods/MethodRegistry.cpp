#include "methods/MethodRegistry.h"

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "baseline/VtkSSAOTechnique.h"
#include "reference/Falloff.h"
#include "screen/ObscuranceTechnique.h"

namespace aokit {

SettingMap parseSettings(const std::string& text) {
  SettingMap out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty()) continue;
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
      throw std::invalid_argument("setting '" + item + "' is not key=value");
    out[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return out;
}

const std::vector<MethodInfo>& methods() {
  static const std::vector<MethodInfo> all = {
      {"none", "no AO: the base frame", {""}, {}},
      {"vtkssao", "VTK's vtkSSAOPass, radius R, bias 0.01 R",
       {"kernel=16", "kernel=32", "kernel=64", "kernel=128", "kernel=32,blur=1"},
       {"kernel", "blur", "bias"}},
      // Screen-space obscurances (seed 003). Keys: samples (rays per pixel, 1..64), m (points per ray,
      // 1..4), scale (1 full or 0.5 half resolution), radius (world units, 0 = scene R), falloff
      // (binary|wendland|sqrt|exponential, default the scene's), interleave (shifts|rotations|off),
      // filter, silhouette, transfer (0|1), bias and thickness (silhouette-elimination window), both
      // fractions of R, tolerance (filter depth tolerance, fraction of view depth), guard (guard band,
      // fraction of the screen size on each side, 0..0.5), view
      // (none|ao|normals|depth: debug views). Curve: the seed's criterion (thickness 1) with m = 2
      // and 4 from 2 rays up, a thinner window, the defaults (samples=4: m 4, thickness 0.7, half
      // resolution), 6 rays (the room's best, about 1/3 of vtkSSAOPass(32)'s time with the lean
      // G-buffer), one full-resolution point, and the defaults and 6 rays with a 10 % guard band (the
      // room's edge error: 0.077 -> 0.050 at 512 x 384 for about +3 ms; no change on open scenes).
      {"obscurance", "screen-space obscurances (seed 003): Poisson-disc rays, 4x4 interleave, depth-aware filter",
       {"samples=2,m=2,thickness=1", "samples=4,m=2,thickness=1", "samples=8,m=2,thickness=1",
        "samples=4,m=4,thickness=1", "samples=8,m=4,thickness=1", "samples=4,m=4,thickness=0.5", "samples=4",
        "samples=6", "samples=4,scale=1", "samples=4,guard=0.1", "samples=6,guard=0.1"},
       {"samples", "m", "scale", "radius", "falloff", "interleave", "filter", "silhouette", "transfer", "bias",
        "thickness", "tolerance", "guard", "view"}},
  };
  return all;
}

const MethodInfo& methodInfo(const std::string& name) {
  std::string known;
  for (const auto& m : methods()) {
    if (m.name == name) return m;
    known += (known.empty() ? "" : ", ") + m.name;
  }
  throw std::invalid_argument("unknown method '" + name + "' (known: " + known + ")");
}

namespace {
void checkKeys(const SettingMap& s, const MethodInfo& m) {
  const std::set<std::string> keys(m.keys.begin(), m.keys.end());
  for (const auto& kv : s)
    if (!keys.count(kv.first)) {
      std::string known;
      for (const auto& k : m.keys) known += (known.empty() ? "" : ", ") + k;
      throw std::invalid_argument(m.name + ": unknown setting '" + kv.first + "'" +
                                  (known.empty() ? " (it takes none)" : " (known: " + known + ")"));
    }
}
}  // namespace

int settingInt(const SettingMap& s, const std::string& method, const std::string& key, int fallback, int lo, int hi) {
  auto it = s.find(key);
  if (it == s.end()) return fallback;
  std::size_t used = 0;
  long v = 0;
  try {
    v = std::stol(it->second, &used);
  } catch (...) {
    used = 0;
  }
  if (used != it->second.size() || v < lo || v > hi)
    throw std::invalid_argument(method + ": " + key + " must be an integer in " + std::to_string(lo) + ".." +
                                std::to_string(hi) + ", got '" + it->second + "'");
  return static_cast<int>(v);
}

double settingDouble(const SettingMap& s, const std::string& method, const std::string& key, double fallback,
                     double lo, double hi) {
  auto it = s.find(key);
  if (it == s.end()) return fallback;
  std::size_t used = 0;
  double v = NAN;
  try {
    v = std::stod(it->second, &used);
  } catch (...) {
    used = 0;
  }
  if (used != it->second.size() || !std::isfinite(v) || v < lo || v > hi) {
    std::ostringstream msg;
    msg << method << ": " << key << " must be a number in " << lo << ".." << hi << ", got '" << it->second << "'";
    throw std::invalid_argument(msg.str());
  }
  return v;
}

bool settingBool(const SettingMap& s, const std::string& method, const std::string& key, bool fallback) {
  auto it = s.find(key);
  if (it == s.end()) return fallback;
  if (it->second == "1" || it->second == "true" || it->second == "on") return true;
  if (it->second == "0" || it->second == "false" || it->second == "off") return false;
  throw std::invalid_argument(method + ": " + key + " must be 0 or 1, got '" + it->second + "'");
}

std::shared_ptr<AOTechnique> makeTechnique(const std::string& method, const std::string& setting) {
  const MethodInfo& info = methodInfo(method);
  const SettingMap s = parseSettings(setting);
  checkKeys(s, info);
  if (method == "none") return nullptr;
  if (method == "vtkssao") {
    VtkSSAOSettings v;
    v.kernelSize = static_cast<unsigned>(settingInt(s, method, "kernel", 32, 1, 1000));
    v.blur = settingBool(s, method, "blur", false);
    v.biasFraction = settingDouble(s, method, "bias", 0.01, 0.0, 1.0);
    return std::make_shared<VtkSSAOTechnique>(v);
  }
  if (method == "obscurance") {
    ObscuranceSettings o;
    o.samples = settingInt(s, method, "samples", o.samples, 1, 64);
    o.pointsPerRay = settingInt(s, method, "m", o.pointsPerRay, 1, 4);
    o.resolutionScale = settingDouble(s, method, "scale", o.resolutionScale, 0.5, 1.0);
    o.radius = settingDouble(s, method, "radius", o.radius, 0.0, 1e30);
    if (s.count("falloff")) {
      try {
        o.falloff = parseFalloff(s.at("falloff"));
      } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(method + ": " + e.what());
      }
    }
    if (s.count("interleave")) {
      const std::string& v = s.at("interleave");
      if (v == "shifts" || v == "1") o.interleave = Interleave::Shifts;
      else if (v == "rotations") o.interleave = Interleave::Rotations;
      else if (v == "off" || v == "0") o.interleave = Interleave::Off;
      else throw std::invalid_argument(method + ": interleave must be shifts, rotations or off, got '" + v + "'");
    }
    o.filter = settingBool(s, method, "filter", o.filter);
    o.silhouetteElimination = settingBool(s, method, "silhouette", o.silhouetteElimination);
    o.ambientTransfer = settingBool(s, method, "transfer", o.ambientTransfer);
    o.bias = settingDouble(s, method, "bias", o.bias, 0.0, 0.5);
    o.thickness = settingDouble(s, method, "thickness", o.thickness, 1e-6, 4.0);
    o.filterTolerance = settingDouble(s, method, "tolerance", o.filterTolerance, 1e-6, 1.0);
    o.guard = settingDouble(s, method, "guard", o.guard, 0.0, 0.5);
    if (s.count("view")) {
      const std::string& v = s.at("view");
      const char* names[] = {"none", "ao", "normals", "depth"};
      int k = 0;
      while (k < 4 && v != names[k]) ++k;
      if (k == 4) throw std::invalid_argument(method + ": view must be none, ao, normals or depth, got '" + v + "'");
      o.debugView = static_cast<ObscuranceDebugView>(k);
    }
    return std::make_shared<ObscuranceTechnique>(o);  // validate() rejects scales other than 1 and 0.5
  }
  throw std::logic_error("method '" + method + "' is listed but not constructible");
}

}  // namespace aokit
