#pragma once
// Every component finite: the one check for points and directions from files, G-buffers and callers.
#include <cmath>

#include <glm/glm.hpp>

namespace aokit {

template <typename T, glm::qualifier Q>
bool allFinite(const glm::vec<3, T, Q>& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace aokit
