#pragma once
// Every AO method by name, with its settings as "key=value,key=value" strings, so the CLI and the
// bench can sweep them. "none" is the base frame (no technique).
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/AOTechnique.h"

namespace aokit {

using SettingMap = std::map<std::string, std::string>;

// Parses "kernel=32,blur=1" (empty -> empty map); throws on a malformed pair.
SettingMap parseSettings(const std::string& text);

struct MethodInfo {
  std::string name;
  std::string summary;
  std::vector<std::string> benchSettings;  // the points of its curve in `aokit bench`
  std::vector<std::string> keys;           // accepted setting keys
};

const std::vector<MethodInfo>& methods();
const MethodInfo& methodInfo(const std::string& name);  // throws listing the known methods

// nullptr for "none". Throws std::invalid_argument naming an unknown method, key or bad value.
std::shared_ptr<AOTechnique> makeTechnique(const std::string& method, const std::string& setting);

// Typed access with one-line errors ("vtkssao: kernel must be an integer in 1..1000, got 'x'").
int settingInt(const SettingMap& s, const std::string& method, const std::string& key, int fallback, int lo, int hi);
double settingDouble(const SettingMap& s, const std::string& method, const std::string& key, double fallback,
                     double lo, double hi);
bool settingBool(const SettingMap& s, const std::string& method, const std::string& key, bool fallback);

}  // namespace aokit
