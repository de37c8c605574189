#pragma once
// Every AO method by name, with its settings as "key=value,key=value" strings, so the CLI and the
// bench can sweep them. Each family registers itself from its own folder (a MethodRegistrar in
// <Family>Method.cpp), listing each setting once: key, kind, unit, range and default. "none" is the
// base frame (no technique).
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/AOTechnique.h"

namespace aokit {

using SettingMap = std::map<std::string, std::string>;

// Parses "kernel=32,blur=1" (empty -> empty map); throws a one-line std::invalid_argument on an
// item that is not key=value, an empty item ("a=1,,b=2") and a key given twice.
SettingMap parseSettings(const std::string& text);

enum class SettingKind { Integer, Number, Flag, Choice };

struct SettingSpec {
  std::string key;
  SettingKind kind = SettingKind::Number;
  std::string description;           // what it is, with its unit ("rays per pixel")
  double min = 0.0, max = 0.0;       // Integer and Number: the accepted range, inclusive
  std::vector<std::string> choices;  // Choice: the accepted words
  std::string defaultText;           // shown in help: the default, or what decides it ("scene")
};

// A method's settings, checked against its specs on construction: unknown keys and values out of
// range or of the wrong kind throw one-line errors naming the method, key, range and value.
class MethodSettings {
 public:
  MethodSettings(const std::string& method, const std::vector<SettingSpec>& specs, const SettingMap& values);
  bool has(const std::string& key) const { return values_.count(key) != 0; }
  int integer(const std::string& key, int fallback) const;
  double number(const std::string& key, double fallback) const;
  bool flag(const std::string& key, bool fallback) const;
  // The choice's index in the spec's choices, or fallback when not given.
  int choice(const std::string& key, int fallback) const;

 private:
  const SettingSpec& spec(const std::string& key) const;
  std::string method_;
  const std::vector<SettingSpec>& specs_;
  SettingMap values_;
};

struct MethodInfo {
  std::string name;
  std::string summary;
  int order = 100;  // listing order (the base frame and the baseline first)
  std::vector<SettingSpec> settings;
  std::vector<std::string> benchSettings;  // the points of its curve in `aokit bench`
  // Builds the technique; nullptr means the base frame ("none").
  std::function<std::shared_ptr<AOTechnique>(const MethodSettings&)> make;
};

// Registers a method at static-initialization time: `static MethodRegistrar r{{...}};`.
struct MethodRegistrar {
  explicit MethodRegistrar(MethodInfo info);
};

const std::vector<MethodInfo>& methods();               // in listing order
const MethodInfo& methodInfo(const std::string& name);  // throws listing the known methods

// nullptr for "none". Throws std::invalid_argument naming an unknown method, key or bad value.
std::shared_ptr<AOTechnique> makeTechnique(const std::string& method, const std::string& setting);

// A setting's default as a registry lists it: 0.5, 2, 0.01 (no trailing zeros).
std::string defaultNumberText(double v);

// "samples  rays per pixel, 1..64 (default 4)" lines, one per setting, for --help.
std::string settingsHelp(const MethodInfo& method);

}  // namespace aokit
