#pragma once
// Shared by the fuzz targets: a property violation aborts (libFuzzer records the input as a crash),
// and hp::Error is the only exception a parser may throw for bad input.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <glm/glm.hpp>

namespace hp::fuzz {
[[noreturn]] inline void violated(const char* what, const char* file, int line) {
  std::fprintf(stderr, "fuzz property violated at %s:%d: %s\n", file, line, what);
  std::abort();
}
inline bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace hp::fuzz

#define HP_FUZZ_REQUIRE(cond) \
  do {                        \
    if (!(cond)) ::hp::fuzz::violated(#cond, __FILE__, __LINE__); \
  } while (0)
