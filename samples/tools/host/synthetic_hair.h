#pragma once
// Contract: a deterministic, plausible .hair model for tests and benchmarks: `strands` wavy strands
// hanging from roots spread over the upper cap of a sphere (center, radius), with point counts that
// vary per strand and sum to exactly `points` (which must allow 2..65536 points per strand).
#include <glm/glm.hpp>

#include <cstdint>

#include "engine/core/hair/hair_file.h"

namespace hp {
struct SyntheticHairOptions {
  std::uint32_t strands = 1000;
  std::uint32_t points = 64000;
  glm::vec3 center{0.0f};
  float radius = 0.1f;
  float length = 0.3f;
  std::uint32_t seed = 3;
};

HairFileData makeSyntheticHair(const SyntheticHairOptions& options);
}  // namespace hp
