#pragma once
// The one number parser behind every text reader check (OFF, OBJ, PLY, STL, VTK legacy and XML):
// a token is a number only when all of it is one. Library readers parse with stream extraction,
// which takes "1.2.3" as 1.2 and then .3, "0x1g" as 0, and shifts every later value; checking
// each token here first is what keeps them from inventing geometry.
#include <cstdint>
#include <string>
#include <string_view>

namespace aokit {

// Plain decimal: [+-]digits[.digits][(e|E)[+-]digits], at least one digit before the exponent.
// Spellings of NaN and infinity ("nan", "-inf", "Infinity", "1e999" that overflows) are numbers
// too, and parse to a non-finite value that the caller refuses in its own words. Hexadecimal
// ("0x1p3"), empty tokens and trailing characters are not numbers.
bool parseReal(std::string_view token, double& value);

// Decimal integer with an optional sign, all of the token, within [min, max].
bool parseInteger(std::string_view token, long long min, long long max, long long& value);

// Whether `v` is a finite float once stored as one (|v| <= FLT_MAX; beyond it the conversion
// would overflow, which C++ leaves undefined).
bool finiteAsFloat(double v);

// A coordinate of a position: a number that is finite as a float (what the mesh stores).
// Throws std::runtime_error "<where>: '<token>' is not a number" or
// "<where> has a NaN or infinite coordinate".
float parseCoordinate(std::string_view token, const std::string& where);

// Any other real field (a normal, a colour): a number, NaN and infinity allowed.
// Throws "<where>: '<token>' is not a number".
double parseRealField(std::string_view token, const std::string& where);

// Non-negative decimal count below 2^32. Throws "<what>: '<token>' is not a count" or
// "<what> <token> is too large".
std::uint64_t parseCount(std::string_view token, const std::string& what);

// At most 40 characters, control and non-ASCII bytes as '?': safe inside a one-line message.
std::string printable(std::string_view s);

}  // namespace aokit
