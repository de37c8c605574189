#pragma once
// Every AO method by name, with its settings as "key=value,key=value" strings, so the CLI and the
// bench can sweep them. Each family registers itself from its own folder (a MethodRegistrar in
// <Family>Method.cpp) with its schema (settings/Schema.h), which says everything about its
// settings, and the bench settings that form its curve. "none" is the base frame (no technique).
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/AOTechnique.h"
#include "settings/Schema.h"

namespace aokit {

struct MethodInfo {
  std::string name;
  std::string summary;
  int order = 100;  // listing order (the base frame and the baseline first)
  std::vector<SettingInfo> settings;
  std::vector<std::string> benchSettings;  // the points of its curve in `aokit bench`
  // Builds the technique from checked settings; nullptr means the base frame ("none"). Throws
  // std::invalid_argument naming the method, key, range and value.
  std::function<std::shared_ptr<AOTechnique>(const SettingMap&)> make;
};

// A family's entry: its settings come from the schema, and make() gets a validated struct.
template <class S, class Make>
MethodInfo familyMethod(std::string name, std::string summary, int order, const Schema<S>& schema,
                        std::vector<std::string> bench, Make make) {
  MethodInfo m;
  m.name = std::move(name);
  m.summary = std::move(summary);
  m.order = order;
  m.settings = schema.infos();
  m.benchSettings = std::move(bench);
  m.make = [&schema, make](const SettingMap& values) -> std::shared_ptr<AOTechnique> {
    return make(schema.parse(values));
  };
  return m;
}

// Registers a method at static-initialization time: `static MethodRegistrar r{familyMethod(...)};`.
struct MethodRegistrar {
  explicit MethodRegistrar(MethodInfo info);
};

const std::vector<MethodInfo>& methods();               // in listing order
const MethodInfo& methodInfo(const std::string& name);  // throws listing the known methods

// nullptr for "none". Throws std::invalid_argument naming an unknown method, key or bad value.
std::shared_ptr<AOTechnique> makeTechnique(const std::string& method, const std::string& setting);

// "  samples: rays per pixel; an integer in 1..64 (default 4)" lines, one per setting, for --help.
std::string settingsHelp(const MethodInfo& method);

}  // namespace aokit
