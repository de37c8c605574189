#include "io/JsonField.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace aokit {
namespace {

std::string shortNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

std::string range(double min, double max) {
  if (max >= 1e300) return ">= " + shortNumber(min);
  return "in [" + shortNumber(min) + ", " + shortNumber(max) + "]";
}

}  // namespace

void JsonField::fail(const std::string& problem) const {
  throw std::runtime_error(file_ + ": " + (path_.empty() ? std::string("top level") : path_) + ": " + problem);
}

void JsonField::allowOnly(std::initializer_list<const char*> allowed) const {
  if (!value_.is_object()) fail("expected an object");
  for (const auto& item : value_.items()) {
    bool known = false;
    for (const char* k : allowed) known = known || item.key() == k;
    if (known) continue;
    std::string list;
    for (const char* k : allowed) list += (list.empty() ? "" : ", ") + std::string(k);
    JsonField(item.value(), file_, path_.empty() ? item.key() : path_ + "." + item.key())
        .fail("unknown key (allowed here: " + list + ")");
  }
}

bool JsonField::has(const char* key) const { return value_.is_object() && value_.contains(key); }

JsonField JsonField::operator[](const char* key) const {
  if (!value_.is_object()) fail("expected an object");
  const auto it = value_.find(key);
  if (it == value_.end()) fail(std::string("missing required key '") + key + "'");
  return JsonField(*it, file_, path_.empty() ? key : path_ + "." + key);
}

std::size_t JsonField::size() const {
  if (!value_.is_array()) fail("expected an array");
  return value_.size();
}

JsonField JsonField::operator[](std::size_t i) const {
  if (!value_.is_array() || i >= value_.size()) fail("expected an array of at least " + std::to_string(i + 1));
  return JsonField(value_[i], file_, path_ + "[" + std::to_string(i) + "]");
}

std::string JsonField::string() const {
  if (!value_.is_string()) fail("expected a string");
  return value_.get<std::string>();
}

bool JsonField::boolean() const {
  if (!value_.is_boolean()) fail("expected true or false");
  return value_.get<bool>();
}

double JsonField::number(double min, double max) const {
  if (!value_.is_number()) fail("expected a number");
  const double v = value_.get<double>();
  if (!std::isfinite(v)) fail("expected a finite number");
  if (v < min || v > max) fail("expected a number " + range(min, max));
  return v;
}

double JsonField::number(const NumberRange& range) const {
  if (!value_.is_number()) fail("expected a number");
  const double v = value_.get<double>();
  if (!range.contains(v)) fail("expected " + range.describe());
  return v;
}

double JsonField::positive() const { return number(limits::kLength); }

long long JsonField::whole(const NumberRange& range) const {
  if (!value_.is_number_integer()) fail("expected " + range.describe());
  const double v = value_.is_number_unsigned() ? double(value_.get<std::uint64_t>()) : double(value_.get<long long>());
  if (!range.contains(v)) fail("expected " + range.describe());
  return value_.is_number_unsigned() ? static_cast<long long>(value_.get<std::uint64_t>()) : value_.get<long long>();
}

int JsonField::integer(int min, int max) const {
  if (!value_.is_number_integer()) fail("expected an integer");
  const auto v = value_.get<long long>();
  if (v < min || v > max) fail("expected an integer " + range(min, max));
  return static_cast<int>(v);
}

std::vector<double> JsonField::numbers(std::size_t n, double min, double max, const std::string& what) const {
  if (!value_.is_array() || value_.size() != n) fail("expected " + what);
  std::vector<double> out;
  for (const auto& v : value_) {
    if (!v.is_number()) fail("expected " + what);
    const double d = v.get<double>();
    if (!std::isfinite(d) || d < min || d > max) fail("expected " + what);
    out.push_back(d);
  }
  return out;
}

glm::dvec3 JsonField::vec3() const {
  const auto v = numbers(3, limits::kCoordinate.min, limits::kCoordinate.max,
                         "3 finite numbers in [" + shortNumber(limits::kCoordinate.min) + ", " +
                             shortNumber(limits::kCoordinate.max) + "]");
  return {v[0], v[1], v[2]};
}

}  // namespace aokit
