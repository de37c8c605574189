#pragma once
// Strict, typed access to one value of a parsed JSON document. Every failure throws
// std::runtime_error "<file>: <json path>: <problem>", e.g.
// "scene.json: objects[2].albedo: expected 3 numbers in [0, 1]".
#include <initializer_list>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "io/SceneLimits.h"

namespace aokit {

class JsonField {
 public:
  JsonField(const nlohmann::json& value, std::string file, std::string path = {})
      : value_(value), file_(std::move(file)), path_(std::move(path)) {}

  const nlohmann::json& json() const { return value_; }
  const std::string& path() const { return path_; }
  [[noreturn]] void fail(const std::string& problem) const;

  // Objects: reject keys outside `allowed`; reach members.
  void allowOnly(std::initializer_list<const char*> allowed) const;
  bool has(const char* key) const;
  JsonField operator[](const char* key) const;  // missing key: fails
  // Arrays.
  std::size_t size() const;  // fails unless an array
  JsonField operator[](std::size_t i) const;

  std::string string() const;
  bool boolean() const;
  double number(double min = -1e300, double max = 1e300) const;  // finite, in [min, max]
  double number(const NumberRange& range) const;                 // "expected <range.describe()>"
  double positive() const;                                       // limits::kLength: > 0, at most 1e15
  int integer(int min, int max) const;
  long long whole(const NumberRange& range) const;               // an integer JSON number in range
  // Exactly n numbers in [min, max]; `what` words the error ("3 numbers in [0, 1]").
  std::vector<double> numbers(std::size_t n, double min, double max, const std::string& what) const;
  glm::dvec3 vec3() const;  // 3 numbers within limits::kCoordinate

 private:
  const nlohmann::json& value_;
  std::string file_, path_;
};

}  // namespace aokit
