#pragma once
// Contract: Cem Yuksel's .hair format (docs/THEORY.md §8.1), in memory. Arrays that the file lacks are
// empty vectors; the header defaults stand in for them. encodeHair(decodeHair(bytes)) == bytes for
// every file decodeHair accepts (the info block is kept verbatim), so a round trip is byte-exact.
// decodeHair validates everything before trusting it and throws hp::Error naming the source and the
// problem; array sizes are checked against the byte count before anything is allocated.
#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace hp {
namespace hairflags {
inline constexpr std::uint32_t kSegments = 1, kPoints = 2, kThickness = 4, kTransparency = 8, kColors = 16;
}

struct HairFileData {
  std::uint32_t strandCount = 0;
  std::uint32_t defaultSegments = 0;       // segments of every strand when `segments` is empty
  float defaultThickness = 1.0f;
  float defaultTransparency = 0.0f;
  glm::vec3 defaultColor{1.0f};
  std::array<char, 88> info{};             // free text, NUL-padded, kept verbatim
  std::vector<std::uint16_t> segments;     // per strand, or empty
  std::vector<glm::vec3> points;           // all strands back to back, root first
  std::vector<float> thickness;            // per point, or empty
  std::vector<float> transparency;         // per point, or empty
  std::vector<glm::vec3> colors;           // per point, or empty

  std::uint32_t pointCount() const { return static_cast<std::uint32_t>(points.size()); }
  std::uint32_t strandPointCount(std::uint32_t strand) const {
    return (segments.empty() ? defaultSegments : segments[strand]) + 1u;
  }
  std::uint32_t arrayFlags() const;
  std::vector<std::uint32_t> strandOffsets() const;  // strandCount + 1 prefix sums of point counts
  std::string infoText() const;
  void setInfoText(const std::string& text);  // truncated to 87 characters
};

HairFileData decodeHair(std::span<const std::byte> bytes, const std::string& source);
std::vector<std::byte> encodeHair(const HairFileData& data);  // throws if data is inconsistent
HairFileData readHairFile(const std::filesystem::path& path);
void writeHairFile(const std::filesystem::path& path, const HairFileData& data);  // atomic

// Throws hp::Error (prefixed by `source`) unless the arrays agree with the counts and the strands
// are usable: at least one strand, every strand >= 2 points, all points finite.
void validateHairData(const HairFileData& data, const std::string& source);
}  // namespace hp
