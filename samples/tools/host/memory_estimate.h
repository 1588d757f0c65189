#pragma once
// Contract: up-front host memory estimates for the memory-heavy runs, so a run that cannot fit is
// refused with its estimate before it starts instead of growing until the machine swaps or kills it.
// availableHostBytes() is the kernel's MemAvailable (/proc/meminfo), or 0 where it cannot be read;
// requireHostMemory() throws hp::Error naming the run, its estimate and the limit when the estimate
// exceeds the limit (the given one, else what is available; no check when neither is known).
#include <cstdint>
#include <string>

namespace hp {
std::uint64_t availableHostBytes();
// What `reference` holds for a width x height frame of `strandPoints` strand points: the radiance and
// coverage images, the output's encoded copy and the curves' share of Embree's scene.
std::uint64_t referenceHostBytes(std::uint32_t width, std::uint32_t height, std::uint64_t strandPoints);
std::string gibibytes(std::uint64_t bytes);  // "4.3 GiB"
void requireHostMemory(const std::string& run, std::uint64_t estimate, std::uint64_t limit);
}  // namespace hp
