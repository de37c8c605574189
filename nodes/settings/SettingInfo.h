#pragma once
// What can be known of one setting without its struct (settings/Schema.h holds the structs'
// tables): key, kind, range, help and default, for --help, the method registry, PrintSelf, and the
// Python and ParaView layers. Plus the text forms every reader shares: "key=value" lists and the
// value parsers (numbers through io/TextNumbers, so "0x1p1" or "1e" are not numbers anywhere).
#include <map>
#include <string>
#include <vector>

namespace aokit {

using SettingMap = std::map<std::string, std::string>;

// Parses "kernel=32,blur=1" (empty -> empty map); throws a one-line std::invalid_argument on an
// item that is not key=value, an empty item ("a=1,,b=2") and a key given twice.
SettingMap parseSettings(const std::string& text);

enum class SettingKind { Integer, Number, Flag, Choice, Text };

// [lo, hi], either end possibly open.
struct Interval {
  double lo = 0.0, hi = 0.0;
  bool loOpen = false, hiOpen = false;
  static Interval closed(double lo, double hi) { return {lo, hi, false, false}; }
  static Interval aboveZero(double hi) { return {0.0, hi, true, false}; }  // (0, hi]
  bool contains(double v) const;
  std::string text() const;  // "0..0.5", "(0, 4]"
};

struct SettingInfo {
  std::string key;
  SettingKind kind = SettingKind::Number;
  std::string help;                  // what it is, with its unit
  Interval range;                    // Integer, Number
  std::string zeroMeans;             // Integer, Number: non-empty when 0 is accepted too and means this
  std::string zeroWord;              // Integer: a word that stands for that 0 in text ("auto")
  std::vector<std::string> choices;  // Choice: the accepted words
  std::string defaultText;           // the value of a default-constructed settings struct

  // Integer and Number: whether v is accepted (finite, in range or the meaningful 0).
  bool accepts(double v) const;
  // "an integer in 1..64", "0 (auto) or an integer in 2..128", "a number in (0, 4]", "0 or 1",
  // "one of none, ao, normals".
  std::string rangeText() const;
};

// A double as short text that reads back to the same value: 0.5, 2, 0.01, 1e+15.
std::string numberText(double v);
// All of `text` a decimal number (io/TextNumbers), finite.
bool parseNumberSetting(const std::string& text, double& v);
// All of `text` a decimal integer that fits in a long long.
bool parseIntegerSetting(const std::string& text, long long& v);
// 1/on/true or 0/off/false.
bool parseFlagSetting(const std::string& text, bool& v);
// "  key: help; range (default d)" lines.
std::string settingsHelpText(const std::vector<SettingInfo>& settings);
// "<family>: unknown setting 'k' (known: a, b)" or "(it takes none)".
std::string unknownSettingMessage(const std::string& family, const std::string& key, const std::vector<std::string>& known);

}  // namespace aokit
