// TressFX .tfxbone decoding. Properties of an accepted file: at least one bone, names within the length limit,
// every influence's bone in the list or -1 with weight 0, weights finite, not negative and not all 0,
// decode(encode(d)) == d, and the per-guide skinning it gives either refuses with hp::Error or has weights
// that are finite, not negative and sum to 1 with bones inside the list.
#include <cmath>
#include <cstdint>
#include <span>

#include "engine/core/error.h"
#include "engine/core/hair/tfx_bone_file.h"
#include "tests/fuzz/fuzz_check.h"

namespace {
bool sameStrands(const hp::TfxBoneData& a, const hp::TfxBoneData& b) {
  if (a.strands.size() != b.strands.size()) return false;
  for (std::size_t i = 0; i < a.strands.size(); ++i)
    if (a.strands[i].strand != b.strands[i].strand || a.strands[i].bones != b.strands[i].bones ||
        a.strands[i].weights != b.strands[i].weights)
      return false;
  return true;
}

void checkAccepted(const hp::TfxBoneData& d) {
  HP_FUZZ_REQUIRE(!d.boneNames.empty() && d.boneNames.size() == d.boneIndices.size());
  for (const auto& name : d.boneNames) HP_FUZZ_REQUIRE(name.size() < hp::kTfxBoneMaxNameBytes);
  for (const auto& s : d.strands) {
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
      HP_FUZZ_REQUIRE(std::isfinite(s.weights[k]) && s.weights[k] >= 0.0f);
      HP_FUZZ_REQUIRE(s.bones[k] >= -1 && s.bones[k] < std::int64_t(d.boneNames.size()));
      HP_FUZZ_REQUIRE(s.bones[k] != -1 || s.weights[k] == 0.0f);
      sum += s.weights[k];
    }
    HP_FUZZ_REQUIRE(sum > 0.0f);
  }
  const hp::TfxBoneData again = hp::decodeTfxBone(hp::encodeTfxBone(d), "again.tfxbone");
  HP_FUZZ_REQUIRE(again.boneNames == d.boneNames && again.boneIndices == d.boneIndices && sameStrands(again, d));
}

void checkSkin(const hp::TfxBoneData& d) {
  const std::uint32_t guides = std::uint32_t(std::min<std::size_t>(d.strands.size() + 3, 1u << 16));
  std::vector<hp::gpu::SkinWeights> skin;
  try {
    skin = hp::tfxBoneSkinWeights(d, guides, "fuzz.tfxbone");
  } catch (const hp::Error&) {
    return;
  }
  HP_FUZZ_REQUIRE(skin.size() == guides);
  for (const auto& s : skin) {
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
      HP_FUZZ_REQUIRE(std::isfinite(s.weights[k]) && s.weights[k] >= 0.0f && s.bones[k] < d.boneNames.size());
      sum += s.weights[k];
    }
    HP_FUZZ_REQUIRE(std::abs(sum - 1.0f) < 1e-4f);
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  hp::TfxBoneData d;
  try {
    d = hp::decodeTfxBone(bytes, "fuzz.tfxbone");
  } catch (const hp::Error&) {
    return 0;
  }
  checkAccepted(d);
  checkSkin(d);
  return 0;
}
