#pragma once
// Contract: 64-bit FNV-1a over bytes, continuing from `h` (the offset basis to start): a fast, well-spread hash
// for keys and checksums against accidents (not a defence against a crafted input).
#include <cstddef>
#include <cstdint>
#include <span>

namespace hp {
inline constexpr std::uint64_t kFnvOffsetBasis = 14695981039346656037ull;
inline constexpr std::uint64_t kFnvPrime = 1099511628211ull;

inline std::uint64_t fnv1a(std::span<const std::byte> bytes, std::uint64_t h = kFnvOffsetBasis) {
  for (std::byte b : bytes) h = (h ^ std::to_integer<std::uint64_t>(b)) * kFnvPrime;
  return h;
}
}  // namespace hp
