// The `hairpipe brdf` query table. Properties of an accepted table: at least one row, and every L, V
// and T a finite unit vector.
#include <cmath>
#include <cstdint>
#include <string_view>

#include "engine/core/error.h"
#include "samples/cli/brdf_queries.h"
#include "tests/fuzz/fuzz_check.h"

namespace {
bool unit(const glm::vec3& v) { return hp::fuzz::finite(v) && std::abs(glm::length(v) - 1.0f) < 1e-5f; }
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const auto rows = hp::cli::parseBrdfQueries(text, "fuzz.csv");
    HP_FUZZ_REQUIRE(!rows.empty());
    for (const auto& r : rows) HP_FUZZ_REQUIRE(unit(r.L) && unit(r.V) && unit(r.T));
  } catch (const hp::Error&) {
  }
  return 0;
}
