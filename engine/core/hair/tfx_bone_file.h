#pragma once
// Contract: AMD TressFX bone skinning files (.tfxbone, docs/THEORY.md §8.3), little-endian int32 / float32:
// the bone count, per bone its index, name length (with the terminating NUL) and name; then the strand
// count and per strand its index and 4 (bone, weight) pairs, the bone being a position in the file's bone
// list or -1 for none. decodeTfxBone checks everything before allocating and refuses by hp::Error naming
// the source, the record and the field: counts that the file cannot hold (sizes in 64 bits), names longer
// than kTfxBoneMaxNameBytes or without their NUL, bones outside the list, -1 with a weight, weights not
// finite or negative or summing to 0, and bytes left over. tfxBoneSkinWeights turns the strands' weights
// into the simulation's per-guide skinning (ScalpInput Bones; weights normalised to sum 1, -1 to bone 0
// with weight 0), guides past the file's strands taking its last strand's weights as TressFX does.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "shaders/shared/simulate.h"

namespace hp {
inline constexpr std::size_t kTfxBoneMaxNameBytes = 1024;

struct TfxStrandSkin {
  std::int32_t strand = 0;                  // the file's strand index (TressFX does not use it either)
  std::array<std::int32_t, 4> bones{};      // positions in TfxBoneData::boneNames, -1: none
  std::array<float, 4> weights{};
};

struct TfxBoneData {
  std::vector<std::int32_t> boneIndices;   // as stored per bone (the exporter's numbering)
  std::vector<std::string> boneNames;
  std::vector<TfxStrandSkin> strands;
};

TfxBoneData decodeTfxBone(std::span<const std::byte> bytes, const std::string& source);
TfxBoneData readTfxBoneFile(const std::filesystem::path& path);
std::vector<std::byte> encodeTfxBone(const TfxBoneData& data);  // for tests and tools

// Per guide, for `guideCount` guides: hp::Error when the file has no strands or more than the guides.
std::vector<gpu::SkinWeights> tfxBoneSkinWeights(const TfxBoneData& data, std::uint32_t guideCount,
                                                 const std::string& source);
}  // namespace hp
