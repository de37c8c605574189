#include "methods/MethodRegistry.h"

#include <algorithm>
#include <stdexcept>

namespace aokit {

namespace {

std::vector<MethodInfo>& registry() {
  static std::vector<MethodInfo> all;
  return all;
}

// The base frame: no technique, no settings.
const MethodRegistrar none{[] {
  MethodInfo m;
  m.name = "none";
  m.summary = "no AO: the base frame";
  m.order = 0;
  m.benchSettings = {""};
  m.make = [](const SettingMap& values) -> std::shared_ptr<AOTechnique> {
    if (!values.empty()) throw std::invalid_argument(unknownSettingMessage("none", values.begin()->first, {}));
    return nullptr;
  };
  return m;
}()};

}  // namespace

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
  std::string known;
  for (const auto& m : methods()) {
    if (m.name == name) return m;
    known += (known.empty() ? "" : ", ") + m.name;
  }
  throw std::invalid_argument("unknown method '" + name + "' (known: " + known + ")");
}

std::shared_ptr<AOTechnique> makeTechnique(const std::string& method, const std::string& setting) {
  const MethodInfo& info = methodInfo(method);
  SettingMap values;
  try {
    values = parseSettings(setting);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(method + ": " + e.what());
  }
  return info.make(values);
}

std::string settingsHelp(const MethodInfo& m) { return settingsHelpText(m.settings); }

}  // namespace aokit
