#pragma once
// Internal to the mesh prechecks: tokenizing and number parsing for text formats, and the checks
// themselves (one file per format).
#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace aokit {

// Next non-blank line split on whitespace; false at the end of the file.
bool nextTokens(std::istream& in, std::vector<std::string>& tokens);
std::string trim(const std::string& s);
// At most 40 characters, control bytes as '?': safe to put in a one-line message.
std::string printable(const std::string& s);
// Whole-token parses; parseCount throws "<what>: 'tok' is not a count" (non-negative, < 2^32).
bool parseNumber(const std::string& token, double& value);
std::uint64_t parseCount(const std::string& token, const std::string& what);

void precheckOff(const std::string& path, std::uintmax_t fileSize);
void precheckPly(const std::string& path, std::uintmax_t fileSize);
void precheckObj(const std::string& path);
void precheckStl(const std::string& path, std::uintmax_t fileSize);

}  // namespace aokit
