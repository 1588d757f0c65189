// Decoding and validation of .hair files (docs/THEORY.md §8.1).
#include <bit>
#include <cmath>
#include <cstring>

#include "engine/core/error.h"
#include "engine/core/hair/hair_file.h"
#include "engine/core/hair/input_file.h"

namespace hp {
static_assert(std::endian::native == std::endian::little, ".hair is little-endian; so is every target");

namespace {
constexpr std::size_t kHeaderSize = 128;
constexpr std::uint32_t kKnownFlags = 31;

template <typename T>
T load(std::span<const std::byte> bytes, std::size_t offset) {
  T value;
  std::memcpy(&value, bytes.data() + offset, sizeof(T));
  return value;
}

template <typename T>
std::vector<T> loadArray(std::span<const std::byte> bytes, std::size_t& offset, std::size_t count) {
  std::vector<T> out(count);
  std::memcpy(out.data(), bytes.data() + offset, count * sizeof(T));
  offset += count * sizeof(T);
  return out;
}

std::string printableSignature(std::span<const std::byte> bytes) {
  std::string s;
  for (int i = 0; i < 4; ++i) {
    auto c = static_cast<unsigned char>(bytes[i]);
    s += (c >= 32 && c < 127) ? std::string(1, char(c)) : "\\x" + std::to_string(c);
  }
  return s;
}

// Array bytes the header announces, in 64 bits so hostile counts cannot overflow.
std::uint64_t announcedArrayBytes(std::uint32_t flags, std::uint64_t strands, std::uint64_t points) {
  std::uint64_t total = 0;
  if (flags & hairflags::kSegments) total += 2 * strands;
  if (flags & hairflags::kPoints) total += 12 * points;
  if (flags & hairflags::kThickness) total += 4 * points;
  if (flags & hairflags::kTransparency) total += 4 * points;
  if (flags & hairflags::kColors) total += 12 * points;
  return total;
}

void checkHeader(std::span<const std::byte> bytes, const std::string& source) {
  if (bytes.size() < kHeaderSize)
    throw Error(source + ": short header: " + std::to_string(bytes.size()) +
                " bytes, a .hair header has 128");
  if (std::memcmp(bytes.data(), "HAIR", 4) != 0)
    throw Error(source + ": wrong signature \"" + printableSignature(bytes) + "\" (expected \"HAIR\")");
  auto flags = load<std::uint32_t>(bytes, 12);
  if (flags & ~kKnownFlags) throw Error(source + ": unknown array flags " + std::to_string(flags));
  if (!(flags & hairflags::kPoints)) throw Error(source + ": the file has no points array");
  if (load<std::uint32_t>(bytes, 4) == 0) throw Error(source + ": zero strands");
  // More strands than points is impossible; checked here, before a loop over a hostile strand count
  // (up to 4 billion) could begin. The points array must be in the file, so this bounds the loop by
  // the file size; the per-strand check then names a strand with too few points.
  if (load<std::uint32_t>(bytes, 4) > load<std::uint32_t>(bytes, 8))
    throw Error(source + ": " + std::to_string(load<std::uint32_t>(bytes, 4)) + " strands but only " +
                std::to_string(load<std::uint32_t>(bytes, 8)) + " points");
  std::uint64_t need = announcedArrayBytes(flags, load<std::uint32_t>(bytes, 4), load<std::uint32_t>(bytes, 8));
  std::uint64_t have = bytes.size() - kHeaderSize;
  if (have < need)
    throw Error(source + ": truncated arrays: the header's counts need " + std::to_string(need) +
                " bytes after the header, the file has " + std::to_string(have));
  if (have > need)
    throw Error(source + ": " + std::to_string(have - need) + " unexpected bytes after the arrays");
}

void checkStrandSizes(const HairFileData& d, const std::string& source) {
  std::uint64_t sum = 0;
  for (std::uint32_t i = 0; i < d.strandCount; ++i) {
    // In 64 bits: a default of 2^32 - 1 segments would wrap strandPointCount to 0.
    const std::uint64_t segments = d.segments.empty() ? d.defaultSegments : d.segments[i];
    if (segments == 0)
      throw Error(source + ": strand " + std::to_string(i) +
                  " has 1 point (0 segments); a strand needs at least 2");
    sum += segments + 1;
  }
  if (sum != d.points.size())
    throw Error(source + ": the strands' segments + 1 sum to " + std::to_string(sum) +
                " points but the point count is " + std::to_string(d.points.size()));
}
}  // namespace

void validateHairData(const HairFileData& d, const std::string& source) {
  if (d.strandCount == 0) throw Error(source + ": zero strands");
  if (!d.segments.empty() && d.segments.size() != d.strandCount)
    throw Error(source + ": " + std::to_string(d.segments.size()) + " segment counts for " +
                std::to_string(d.strandCount) + " strands");
  auto checkPerPoint = [&](std::size_t size, const char* name) {
    if (size != 0 && size != d.points.size())
      throw Error(source + ": " + std::to_string(size) + " " + name + " values for " +
                  std::to_string(d.points.size()) + " points");
  };
  checkPerPoint(d.thickness.size(), "thickness");
  checkPerPoint(d.transparency.size(), "transparency");
  checkPerPoint(d.colors.size(), "color");
  checkStrandSizes(d, source);
  auto offsets = d.strandOffsets();
  for (std::uint32_t s = 0; s < d.strandCount; ++s)
    for (std::uint32_t i = offsets[s]; i < offsets[s + 1]; ++i)
      if (!std::isfinite(d.points[i].x) || !std::isfinite(d.points[i].y) || !std::isfinite(d.points[i].z))
        throw Error(source + ": point " + std::to_string(i) + " (strand " + std::to_string(s) +
                    ") is not finite (NaN or Inf)");
}

HairFileData decodeHair(std::span<const std::byte> bytes, const std::string& source) {
  checkHeader(bytes, source);
  HairFileData d;
  d.strandCount = load<std::uint32_t>(bytes, 4);
  auto pointCount = load<std::uint32_t>(bytes, 8);
  auto flags = load<std::uint32_t>(bytes, 12);
  d.defaultSegments = load<std::uint32_t>(bytes, 16);
  d.defaultThickness = load<float>(bytes, 20);
  d.defaultTransparency = load<float>(bytes, 24);
  d.defaultColor = load<glm::vec3>(bytes, 28);
  std::memcpy(d.info.data(), bytes.data() + 40, d.info.size());
  std::size_t at = kHeaderSize;
  if (flags & hairflags::kSegments) d.segments = loadArray<std::uint16_t>(bytes, at, d.strandCount);
  d.points = loadArray<glm::vec3>(bytes, at, pointCount);
  if (flags & hairflags::kThickness) d.thickness = loadArray<float>(bytes, at, pointCount);
  if (flags & hairflags::kTransparency) d.transparency = loadArray<float>(bytes, at, pointCount);
  if (flags & hairflags::kColors) d.colors = loadArray<glm::vec3>(bytes, at, pointCount);
  validateHairData(d, source);
  return d;
}

HairFileData readHairFile(const std::filesystem::path& path) {
  return decodeHair(readInputBytes(path, kMaxHairFileBytes), path.string());
}
}  // namespace hp
