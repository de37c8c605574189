#include "methods/MethodRegistry.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace aokit {

namespace {

std::vector<MethodInfo>& registry() {
  static std::vector<MethodInfo> all;
  return all;
}

std::string joined(const std::vector<std::string>& items, const char* sep) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : sep) + s;
  return out;
}

std::string rangeText(const SettingSpec& s) {
  std::ostringstream r;
  switch (s.kind) {
    case SettingKind::Integer: r << "an integer in " << s.min << ".." << s.max; break;
    case SettingKind::Number: r << "a number in " << s.min << ".." << s.max; break;
    case SettingKind::Flag: r << "0 or 1"; break;
    case SettingKind::Choice: r << joined(s.choices, ", "); break;
  }
  return r.str();
}

// The base frame: no technique.
const MethodRegistrar none{{"none", "no AO: the base frame", 0, {}, {""}, nullptr}};

}  // namespace

SettingMap parseSettings(const std::string& text) {
  SettingMap out;
  if (text.empty()) return out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    if (item.empty()) throw std::invalid_argument("settings '" + text + "' hold an empty item");
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == item.size())
      throw std::invalid_argument("setting '" + item + "' is not key=value");
    if (!out.emplace(item.substr(0, eq), item.substr(eq + 1)).second)
      throw std::invalid_argument("setting '" + item.substr(0, eq) + "' is given twice");
  }
  if (text.back() == ',') throw std::invalid_argument("settings '" + text + "' hold an empty item");
  return out;
}

MethodSettings::MethodSettings(const std::string& method, const std::vector<SettingSpec>& specs, const SettingMap& values)
    : method_(method), specs_(specs), values_(values) {
  for (const auto& [key, value] : values_) {
    const SettingSpec& s = spec(key);
    switch (s.kind) {
      case SettingKind::Integer: integer(key, 0); break;
      case SettingKind::Number: number(key, 0.0); break;
      case SettingKind::Flag: flag(key, false); break;
      case SettingKind::Choice: choice(key, 0); break;
    }
  }
}

const SettingSpec& MethodSettings::spec(const std::string& key) const {
  for (const auto& s : specs_)
    if (s.key == key) return s;
  std::vector<std::string> keys;
  for (const auto& s : specs_) keys.push_back(s.key);
  throw std::invalid_argument(method_ + ": unknown setting '" + key + "'" +
                              (keys.empty() ? " (it takes none)" : " (known: " + joined(keys, ", ") + ")"));
}

namespace {
[[noreturn]] void badValue(const std::string& method, const SettingSpec& s, const std::string& value) {
  throw std::invalid_argument(method + ": " + s.key + " must be " + rangeText(s) + ", got '" + value + "'");
}
}  // namespace

int MethodSettings::integer(const std::string& key, int fallback) const {
  auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  const SettingSpec& s = spec(key);
  std::size_t used = 0;
  long long v = 0;
  try {
    v = std::stoll(it->second, &used);
  } catch (...) {
    used = 0;
  }
  if (used == 0 || used != it->second.size() || v < s.min || v > s.max) badValue(method_, s, it->second);
  return static_cast<int>(v);
}

double MethodSettings::number(const std::string& key, double fallback) const {
  auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  const SettingSpec& s = spec(key);
  std::size_t used = 0;
  double v = NAN;
  try {
    v = std::stod(it->second, &used);
  } catch (...) {
    used = 0;
  }
  if (used == 0 || used != it->second.size() || !std::isfinite(v) || v < s.min || v > s.max)
    badValue(method_, s, it->second);
  return v;
}

bool MethodSettings::flag(const std::string& key, bool fallback) const {
  auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  const std::string& v = it->second;
  if (v == "1" || v == "true" || v == "on") return true;
  if (v == "0" || v == "false" || v == "off") return false;
  badValue(method_, spec(key), v);
}

int MethodSettings::choice(const std::string& key, int fallback) const {
  auto it = values_.find(key);
  if (it == values_.end()) return fallback;
  const SettingSpec& s = spec(key);
  const auto found = std::find(s.choices.begin(), s.choices.end(), it->second);
  if (found == s.choices.end()) badValue(method_, s, it->second);
  return static_cast<int>(found - s.choices.begin());
}

MethodRegistrar::MethodRegistrar(MethodInfo info) {
  auto& all = registry();
  for (const auto& m : all)
    if (m.name == info.name) throw std::logic_error("method '" + info.name + "' registered twice");
  const auto at = std::find_if(all.begin(), all.end(), [&](const MethodInfo& m) {
    return m.order > info.order || (m.order == info.order && m.name > info.name);
  });
  all.insert(at, std::move(info));
}

const std::vector<MethodInfo>& methods() { return registry(); }

const MethodInfo& methodInfo(const std::string& name) {
  std::vector<std::string> known;
  for (const auto& m : methods()) {
    if (m.name == name) return m;
    known.push_back(m.name);
  }
  throw std::invalid_argument("unknown method '" + name + "' (known: " + joined(known, ", ") + ")");
}

std::shared_ptr<AOTechnique> makeTechnique(const std::string& method, const std::string& setting) {
  const MethodInfo& info = methodInfo(method);
  SettingMap values;
  try {
    values = parseSettings(setting);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(method + ": " + e.what());
  }
  const MethodSettings settings(method, info.settings, values);
  return info.make ? info.make(settings) : nullptr;
}

std::string defaultNumberText(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

std::string settingsHelp(const MethodInfo& m) {
  std::string out;
  for (const auto& s : m.settings)
    out += "  " + s.key + ": " + s.description + "; " + rangeText(s) + " (default " + s.defaultText + ")\n";
  return out;
}

}  // namespace aokit
