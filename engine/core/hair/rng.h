#pragma once
// Contract: deterministic, stateless random numbers. hashRandom(seed, index, stream) depends only on its
// three arguments, so any element (a guide, a render strand) can be regenerated alone and in any
// order, on the host or on the GPU (pcgHash is the PCG-based integer hash of Jarzynski & Olano 2020,
// which ports to GLSL as is).
#include <cstdint>

namespace hp {
constexpr std::uint32_t pcgHash(std::uint32_t v) {
  std::uint32_t state = v * 747796405u + 2891336453u;
  std::uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

// Uniform in [0, 1): the top 24 bits of the hash, so every value is exactly representable as float.
constexpr float hashRandom(std::uint32_t seed, std::uint32_t index, std::uint32_t stream) {
  std::uint32_t h = pcgHash(pcgHash(pcgHash(seed) + index) + stream);
  return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}
}  // namespace hp
