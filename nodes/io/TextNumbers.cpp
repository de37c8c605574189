#include "io/TextNumbers.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace aokit {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const char x = (a[i] >= 'A' && a[i] <= 'Z') ? char(a[i] - 'A' + 'a') : a[i];
    if (x != b[i]) return false;
  }
  return true;
}

// Accepts exactly the decimal grammar above, so that from_chars never sees anything else.
bool isDecimal(std::string_view s) {
  std::size_t i = 0, digits = 0;
  while (i < s.size() && isDigit(s[i])) ++i, ++digits;
  if (i < s.size() && s[i] == '.') {
    ++i;
    while (i < s.size() && isDigit(s[i])) ++i, ++digits;
  }
  if (digits == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    const std::size_t start = i;
    while (i < s.size() && isDigit(s[i])) ++i;
    if (i == start) return false;
  }
  return i == s.size();
}

}  // namespace

bool parseReal(std::string_view token, double& value) {
  bool negative = false;
  std::string_view s = token;
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
    negative = s[0] == '-';
    s.remove_prefix(1);
  }
  if (equalsIgnoringCase(s, "nan")) {
    value = std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  if (equalsIgnoringCase(s, "inf") || equalsIgnoringCase(s, "infinity")) {
    value = negative ? -std::numeric_limits<double>::infinity() : std::numeric_limits<double>::infinity();
    return true;
  }
  if (!isDecimal(s)) return false;
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v, std::chars_format::general);
  if (end != s.data() + s.size()) return false;
  if (ec == std::errc::result_out_of_range) {
    // Overflow reads as infinity (refused by callers as non-finite); underflow as zero.
    const auto e = s.find_first_of("eE");
    const bool tiny = e != std::string_view::npos && e + 1 < s.size() && s[e + 1] == '-';
    v = tiny ? 0.0 : std::numeric_limits<double>::infinity();
  } else if (ec != std::errc()) {
    return false;
  }
  value = negative ? -v : v;
  return true;
}

bool parseInteger(std::string_view token, long long min, long long max, long long& value) {
  std::string_view s = token;
  if (!s.empty() && s[0] == '+') s.remove_prefix(1);
  if (s.empty() || !(isDigit(s[0]) || (s[0] == '-' && token[0] != '+' && s.size() > 1 && isDigit(s[1]))))
    return false;
  long long v = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v, 10);
  if (ec != std::errc() || end != s.data() + s.size() || v < min || v > max) return false;
  value = v;
  return true;
}

bool finiteAsFloat(double v) { return std::isfinite(v) && std::fabs(v) <= double(std::numeric_limits<float>::max()); }

float parseCoordinate(std::string_view token, const std::string& where) {
  double v = 0.0;
  if (!parseReal(token, v)) throw std::runtime_error(where + ": '" + printable(token) + "' is not a number");
  if (!finiteAsFloat(v)) throw std::runtime_error(where + " has a NaN or infinite coordinate");
  return static_cast<float>(v);
}

double parseRealField(std::string_view token, const std::string& where) {
  double v = 0.0;
  if (!parseReal(token, v)) throw std::runtime_error(where + ": '" + printable(token) + "' is not a number");
  return v;
}

std::uint64_t parseCount(std::string_view token, const std::string& what) {
  const bool digits = !token.empty() && token.find_first_not_of("0123456789") == std::string_view::npos;
  if (!digits) throw std::runtime_error(what + ": '" + printable(token) + "' is not a count");
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), v, 10);
  if (ec != std::errc() || end != token.data() + token.size() || v >= (std::uint64_t(1) << 32))
    throw std::runtime_error(what + " " + printable(token) + " is too large");
  return v;
}

std::string printable(std::string_view s) {
  std::string out(s.substr(0, 40));
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  return s.size() > 40 ? out + "..." : out;
}

}  // namespace aokit
