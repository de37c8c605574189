#include "methods/MethodRegistry.h"

#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>

#include "baseline/VtkSSAOTechnique.h"

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
  throw std::logic_error("method '" + method + "' is listed but not constructible");
}

}  // namespace aokit
