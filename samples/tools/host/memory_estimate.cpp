#include "samples/tools/host/memory_estimate.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "engine/core/error.h"

namespace hp {
std::uint64_t availableHostBytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024;
  return 0;
}

std::uint64_t referenceHostBytes(std::uint32_t width, std::uint32_t height, std::uint64_t strandPoints) {
  const std::uint64_t pixels = std::uint64_t(width) * height;
  // Radiance (3 floats) and coverage (1 float) per pixel, the output's encoded copy (at most 3 floats,
  // PFM), and per strand point its position, radius and colour plus Embree's curve and BVH share
  // (~96 bytes, measured on the default head's 20,000 strands x 36 points).
  return pixels * (16 + 12) + strandPoints * 128;
}

std::string gibibytes(std::uint64_t bytes) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.1f GiB", double(bytes) / double(1ull << 30));
  return text;
}

void requireHostMemory(const std::string& run, std::uint64_t estimate, std::uint64_t limit) {
  const std::uint64_t available = limit ? limit : availableHostBytes();
  if (available == 0 || estimate <= available) return;
  throw Error(run + " needs about " + gibibytes(estimate) + " of host memory, more than the " + gibibytes(available) +
              (limit ? " allowed (--max-memory)" : " available"));
}
}  // namespace hp
