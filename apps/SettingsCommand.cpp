// aokit settings: every method's settings (key, kind, unit, range, default) from the methods'
// schemas, as text or as JSON (what the ParaView plugin's view properties are generated from).
#include <cstdio>

#include <nlohmann/json.hpp>

#include "Commands.h"
#include "methods/MethodRegistry.h"

namespace aokit::cli {

namespace {
const char* kindName(SettingKind k) {
  switch (k) {
    case SettingKind::Integer: return "integer";
    case SettingKind::Number: return "number";
    case SettingKind::Flag: return "flag";
    case SettingKind::Choice: return "choice";
    case SettingKind::Text: return "text";
  }
  return "text";
}

nlohmann::json settingJson(const SettingInfo& s) {
  // "default" is the value itself; the schema shows an empty text default as the word "empty".
  const bool emptyText = s.kind == SettingKind::Text && s.defaultText == "empty";
  nlohmann::json j{{"key", s.key}, {"kind", kindName(s.kind)}, {"help", s.help},
                   {"range_text", s.rangeText()}, {"default", emptyText ? "" : s.defaultText},
                   {"default_text", s.defaultText}};
  if (s.kind == SettingKind::Integer || s.kind == SettingKind::Number) {
    j["lo"] = s.range.lo;
    j["hi"] = s.range.hi;
    j["lo_open"] = s.range.loOpen;
    j["hi_open"] = s.range.hiOpen;
    j["zero_means"] = s.zeroMeans;
  }
  if (s.kind == SettingKind::Choice) j["choices"] = s.choices;
  return j;
}

void runSettings(const std::string& method, bool json) {
  std::vector<const MethodInfo*> chosen;
  if (method.empty())
    for (const MethodInfo& m : methods()) chosen.push_back(&m);
  else
    chosen.push_back(&methodInfo(method));  // throws listing the known methods
  if (json) {
    nlohmann::json out = nlohmann::json::array();
    for (const MethodInfo* m : chosen) {
      nlohmann::json settings = nlohmann::json::array();
      for (const SettingInfo& s : m->settings) settings.push_back(settingJson(s));
      out.push_back({{"name", m->name}, {"summary", m->summary}, {"settings", settings}});
    }
    std::printf("%s\n", out.dump(1).c_str());
    return;
  }
  for (const MethodInfo* m : chosen) {
    std::printf("%s: %s\n", m->name.c_str(), m->summary.c_str());
    const std::string help = settingsHelp(*m);
    std::printf("%s", help.empty() ? "  (no settings)\n" : help.c_str());
  }
}
}  // namespace

void addSettingsCommand(CLI::App& app) {
  auto method = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  CLI::App* cmd = app.add_subcommand("settings", "list every method's settings: key, unit, range, default");
  cmd->add_option("method", *method, "only this method");
  cmd->add_flag("--json", *json, "as JSON (the ParaView plugin's properties are generated from it)");
  cmd->callback([method, json] { runSettings(*method, *json); });
}

}  // namespace aokit::cli
