#pragma once
// Contract: AMD TressFX 4 asset files (.tfx, docs/THEORY.md §8.2), little-endian: a 160-byte header
// (version, numHairStrands, numVerticesPerStrand, byte offsets of positions, strand UVs, vertex
// UVs, strand thickness, vertex colours; 0 = absent), then the arrays where the offsets say.
// decodeTfx validates everything before allocating: header size, strand count > 0, vertices per
// strand in [2, 64], every present array inside the file and not overlapping the header (sizes in
// 64 bits, so hostile counts cannot overflow), every value finite, inverse masses (w) and strand
// thicknesses not negative. Each refusal is an hp::Error that
// names the source and the field. tfxToHair turns the strands into .hair data (same points, the
// file's strand order), so the .hair import (resampling, root triangulation) applies unchanged.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/hair/hair_file.h"

namespace hp {
inline constexpr std::size_t kTfxHeaderSize = 160;

struct TfxData {
  float version = 4.0f;
  std::uint32_t strandCount = 0;
  std::uint32_t verticesPerStrand = 0;
  std::vector<glm::vec4> positions;   // strandCount * verticesPerStrand; w = inverse mass (0: pinned)
  std::vector<glm::vec2> strandUVs;   // per strand, or empty
  std::vector<glm::vec2> vertexUVs;   // per vertex, or empty
  std::vector<float> strandThickness; // per strand, or empty
  std::vector<glm::vec4> vertexColors;  // per vertex, or empty
};

TfxData decodeTfx(std::span<const std::byte> bytes, const std::string& source);
TfxData readTfxFile(const std::filesystem::path& path);
// Header, positions at 160, then the present optional arrays in header order (for tests and tools).
std::vector<std::byte> encodeTfx(const TfxData& data);
HairFileData tfxToHair(const TfxData& data);
}  // namespace hp
