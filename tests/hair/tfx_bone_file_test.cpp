// TressFX .tfxbone skinning files (docs/THEORY.md §8.3): a generated file reads back its counts and values,
// turns into per-guide skinning (normalised, -1 as bone 0 with weight 0, the last strand's weights for guides
// past the file's strands), and every corruption is refused with a message naming the record and the field.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "engine/core/error.h"
#include "engine/core/hair/tfx_bone_file.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
TfxBoneData threeBones() {
  TfxBoneData d;
  d.boneIndices = {10, 20, 30};
  d.boneNames = {"head", "neck", "jaw"};
  d.strands = {{0, {0, -1, -1, -1}, {1.0f, 0.0f, 0.0f, 0.0f}},
               {1, {0, 2, -1, -1}, {0.5f, 0.5f, 0.0f, 0.0f}},
               {2, {1, 0, 2, -1}, {0.5f, 0.5f, 1.0f, 0.0f}}};  // sums to 2: normalised when used
  return d;
}

std::vector<std::byte> bytesOf(const TfxBoneData& d) { return encodeTfxBone(d); }

template <typename T>
void poke(std::vector<std::byte>& bytes, std::size_t at, T value) {
  std::memcpy(bytes.data() + at, &value, sizeof(T));
}

// Byte positions in threeBones()'s file: bones start at 4, each 8 + name + NUL bytes.
constexpr std::size_t kStrandCountAt = 4 + (8 + 5) + (8 + 5) + (8 + 4);
constexpr std::size_t kFirstStrandAt = kStrandCountAt + 4;
}  // namespace

TEST(TfxBoneFile, AGeneratedFileReadsBackItsCountsAndValues) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "hairpipe_test.tfxbone";
  const std::vector<std::byte> bytes = bytesOf(threeBones());
  EXPECT_EQ(bytes.size(), kFirstStrandAt + 3 * 36);
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  }
  const TfxBoneData d = readTfxBoneFile(path);
  std::filesystem::remove(path);
  EXPECT_EQ(d.boneNames, (std::vector<std::string>{"head", "neck", "jaw"}));
  EXPECT_EQ(d.boneIndices, (std::vector<std::int32_t>{10, 20, 30}));
  ASSERT_EQ(d.strands.size(), 3u);
  EXPECT_EQ(d.strands[1].bones, (std::array<std::int32_t, 4>{0, 2, -1, -1}));
  EXPECT_EQ(d.strands[2].weights, (std::array<float, 4>{0.5f, 0.5f, 1.0f, 0.0f}));
  EXPECT_EQ(d.strands[2].strand, 2);
}

TEST(TfxBoneFile, StrandsBecomeNormalisedSkinningForEveryGuide) {
  const std::vector<gpu::SkinWeights> skin = tfxBoneSkinWeights(threeBones(), 5, "three.tfxbone");
  ASSERT_EQ(skin.size(), 5u);
  EXPECT_EQ(skin[0].bones, glm::uvec4(0, 0, 0, 0));  // -1 becomes bone 0 with weight 0
  EXPECT_EQ(skin[0].weights, glm::vec4(1.0f, 0.0f, 0.0f, 0.0f));
  EXPECT_EQ(skin[2].bones, glm::uvec4(1, 0, 2, 0));
  EXPECT_EQ(skin[2].weights, glm::vec4(0.25f, 0.25f, 0.5f, 0.0f));
  EXPECT_EQ(skin[4].weights, skin[2].weights) << "guides past the file's strands take its last strand's weights";
  EXPECT_ERROR_CONTAINS(tfxBoneSkinWeights(threeBones(), 2, "three.tfxbone"),
                        "three.tfxbone: 3 strands of skinning for 2 guides");
}

TEST(TfxBoneFile, CorruptFilesAreRefusedByRecordAndField) {
  const std::vector<std::byte> good = bytesOf(threeBones());
  struct Case {
    std::vector<std::byte> bytes;
    std::string message;
  };
  std::vector<Case> cases;
  auto with = [&](auto change) {
    std::vector<std::byte> b = good;
    change(b);
    return b;
  };
  cases.push_back({{}, "the bone count needs 4 bytes at byte 0"});
  cases.push_back({with([](auto& b) { poke<std::int32_t>(b, 0, 0); }), "bone count 0 is not positive"});
  cases.push_back({with([](auto& b) { poke<std::int32_t>(b, 0, 0x7fffffff); }), "more than the file holds"});
  cases.push_back({with([](auto& b) { poke<std::int32_t>(b, 8, 5000); }), "bone 0's name length 5000 is outside 1..1024"});
  cases.push_back({with([](auto& b) { poke<char>(b, 16, 'x'); }), "bone 0's name does not end with its NUL"});
  cases.push_back({with([](auto& b) { poke<std::int32_t>(b, kStrandCountAt, 4); }), "strand count 4 needs 144 bytes"});
  cases.push_back({with([](auto& b) { b.push_back(std::byte{1}); }), "the file has 109 left"});
  cases.push_back({with([](auto& b) { poke<std::int32_t>(b, kFirstStrandAt + 4, 3); }),
                   "strand 0 influence 0 names bone 3, the file has 3"});
  cases.push_back({with([](auto& b) { poke<float>(b, kFirstStrandAt + 8, std::nanf("")); }),
                   "strand 0 influence 0 has weight nan"});
  cases.push_back({with([](auto& b) { poke<float>(b, kFirstStrandAt + 16, 0.5f); }),
                   "strand 0 influence 1 has no bone (-1) but weight 0.5"});
  cases.push_back({with([](auto& b) { poke<float>(b, kFirstStrandAt + 8, 0.0f); }), "strand 0's weights sum to 0"});
  cases.push_back({with([](auto& b) { b.resize(b.size() - 3); }), "strand count 3 needs 108 bytes"});
  for (const Case& c : cases) EXPECT_ERROR_CONTAINS(decodeTfxBone(c.bytes, "bad.tfxbone"), c.message);
}
}  // namespace hp
