#include "settings/SettingInfo.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "io/TextNumbers.h"

namespace aokit {

namespace {
std::string joined(const std::vector<std::string>& items, const char* sep) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : sep) + s;
  return out;
}
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

bool Interval::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (loOpen ? !(v > lo) : !(v >= lo)) return false;
  return hiOpen ? v < hi : v <= hi;
}

std::string Interval::text() const {
  if (!loOpen && !hiOpen) return numberText(lo) + ".." + numberText(hi);
  return std::string(loOpen ? "(" : "[") + numberText(lo) + ", " + numberText(hi) + (hiOpen ? ")" : "]");
}

bool SettingInfo::accepts(double v) const {
  if (!zeroMeans.empty() && v == 0.0) return true;
  return range.contains(v);
}

std::string SettingInfo::rangeText() const {
  const std::string zero = zeroMeans.empty() ? "" : (zeroWord.empty() ? "0" : zeroWord) + " (" + zeroMeans + ") or ";
  switch (kind) {
    case SettingKind::Integer: return zero + "an integer in " + range.text();
    case SettingKind::Number: return zero + "a number in " + range.text();
    case SettingKind::Flag: return "0 or 1";
    case SettingKind::Choice: return "one of " + joined(choices, ", ");
    case SettingKind::Text: return "text without ','";
  }
  return "";
}

std::string numberText(double v) {
  if (!std::isfinite(v)) return std::isnan(v) ? "nan" : (v > 0 ? "inf" : "-inf");
  char buffer[32];
  if (v == std::floor(v) && std::abs(v) < 1e16) {  // whole numbers as such: 1000, not 1e+03
    std::snprintf(buffer, sizeof buffer, "%.0f", v);
    return buffer;
  }
  for (int precision = 1; precision <= 17; ++precision) {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, v);
    if (std::strtod(buffer, nullptr) == v) break;
  }
  return buffer;
}

bool parseNumberSetting(const std::string& text, double& v) { return parseReal(text, v) && std::isfinite(v); }

bool parseIntegerSetting(const std::string& text, long long& v) {
  return parseInteger(text, std::numeric_limits<long long>::min(), std::numeric_limits<long long>::max(), v);
}

bool parseFlagSetting(const std::string& text, bool& v) {
  if (text == "1" || text == "true" || text == "on") return v = true, true;
  if (text == "0" || text == "false" || text == "off") return v = false, true;
  return false;
}

std::string settingsHelpText(const std::vector<SettingInfo>& settings) {
  std::string out;
  for (const auto& s : settings)
    out += "  " + s.key + ": " + s.help + "; " + s.rangeText() + " (default " + s.defaultText + ")\n";
  return out;
}

std::string unknownSettingMessage(const std::string& family, const std::string& key, const std::vector<std::string>& known) {
  return family + ": unknown setting '" + key + "'" +
         (known.empty() ? " (it takes none)" : " (known: " + joined(known, ", ") + ")");
}

}  // namespace aokit
