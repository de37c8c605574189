#include "io/PrecheckText.h"

#include <cerrno>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace aokit {

bool nextTokens(std::istream& in, std::vector<std::string>& tokens) {
  std::string line;
  while (std::getline(in, line)) {
    tokens.clear();
    std::istringstream words(line);
    for (std::string w; words >> w;) tokens.push_back(w);
    if (!tokens.empty()) return true;
  }
  return false;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return {};
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

std::string printable(const std::string& s) {
  std::string out = s.substr(0, 40);
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 32 || static_cast<unsigned char>(c) > 126) c = '?';
  return s.size() > 40 ? out + "..." : out;
}

bool parseNumber(const std::string& token, double& value) {
  char* end = nullptr;
  errno = 0;
  value = std::strtod(token.c_str(), &end);
  return end && *end == '\0' && end != token.c_str();
}

std::uint64_t parseCount(const std::string& token, const std::string& what) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(token.c_str(), &end, 10);
  if (token.empty() || token[0] == '-' || !end || *end != '\0')
    throw std::runtime_error(what + ": '" + printable(token) + "' is not a count");
  if (errno == ERANGE || v >= (1ull << 32)) throw std::runtime_error(what + " " + printable(token) + " is too large");
  return v;
}

}  // namespace aokit
