#pragma once
// Tests on the meshes models/fetch-meshes.sh pulls from Debian packages. Without them a test is
// skipped, saying so; with AOKIT_REQUIRE_MESHES=1 (the README's test command sets it) it fails
// instead, so a failed fetch cannot read as green.
#include <cstdlib>
#include <cstring>

#include <gtest/gtest.h>

namespace aokit::test {
inline bool meshesRequired() {
  const char* v = std::getenv("AOKIT_REQUIRE_MESHES");
  return v && std::strcmp(v, "1") == 0;
}
}  // namespace aokit::test

// In a test body: skips (or fails, when meshes are required) unless `present` holds.
#define AOKIT_NEED_MESHES(present, what)                                                       \
  do {                                                                                          \
    if (!(present)) {                                                                           \
      if (aokit::test::meshesRequired()) FAIL() << what << " is missing (AOKIT_REQUIRE_MESHES=1)"; \
      GTEST_SKIP() << "run models/fetch-meshes.sh for " << what;                                \
    }                                                                                           \
  } while (0)
