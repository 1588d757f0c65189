// The packed skin transfer through the disk cache (engine/core/hair/skin_transfer_cache.h): read back bit for bit
// what computing gives, keyed by the whole mesh (a change to any array is another entry), a damaged entry
// computed again.
#include <gtest/gtest.h>

#include <cstring>

#include "engine/core/hair/skin_transfer_cache.h"
#include "shaders/shared/render.h"
#include "tests/hair/hair_test_util.h"

using namespace hp;

namespace {
// Two facing squares of 3 x 3 cells (16 vertices each): each hides part of the other's sky.
HeadMesh facingSquares() {
  HeadMesh mesh;
  for (float z : {0.0f, 1.0f}) {
    const float facing = z == 0.0f ? 1.0f : -1.0f;
    const auto first = std::uint32_t(mesh.positions.size());
    for (int j = 0; j <= 3; ++j)
      for (int i = 0; i <= 3; ++i) {
        mesh.positions.push_back({float(i) / 3.0f - 0.5f, float(j) / 3.0f - 0.5f, z});
        mesh.normals.push_back({0.0f, 0.0f, facing});
      }
    for (std::uint32_t j = 0; j < 3; ++j)
      for (std::uint32_t i = 0; i < 3; ++i) {
        const std::uint32_t a = first + j * 4 + i, b = a + 1, c = a + 5, d = a + 4;
        if (facing > 0) mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
        else mesh.indices.insert(mesh.indices.end(), {a, c, b, a, d, c});
      }
  }
  mesh.scalp.assign(mesh.positions.size(), 0.0f);
  return mesh;
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

std::size_t entries(const std::filesystem::path& folder) {
  return std::size_t(std::distance(std::filesystem::directory_iterator(folder), {}));
}
}  // namespace

TEST(SkinTransferCache, ReadsBackWhatComputingGivesKeyedByTheWholeMesh) {
  test::TempDir dir;
  const DiskCache disk(dir.path());
  const HeadMesh mesh = facingSquares();
  const std::vector<float> computed = packSkinTransfer(mesh);
  ASSERT_EQ(computed.size(), mesh.positions.size() * gpu::SKIN_TRANSFER_FLOATS);
  EXPECT_TRUE(sameBits(packedSkinTransfer(mesh, disk), computed));  // computed and stored
  ASSERT_EQ(entries(dir.path()), 1u);
  const std::filesystem::path entry = std::filesystem::directory_iterator(dir.path())->path();
  const ino_t stored = test::inodeOf(entry);
  EXPECT_TRUE(sameBits(packedSkinTransfer(mesh, disk), computed));  // read back: the entry not written again
  EXPECT_EQ(test::inodeOf(entry), stored) << "computed again instead of read";
  // One scalp weight changed: another mesh, another entry (the scalp changes what the skin reflects).
  HeadMesh scalped = mesh;
  scalped.scalp[5] = 1.0f;
  EXPECT_TRUE(sameBits(packedSkinTransfer(scalped, disk), packSkinTransfer(scalped)));
  EXPECT_EQ(entries(dir.path()), 2u);
  // Every entry damaged (its last byte, the checksum's): computed again, the same values.
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    std::vector<std::byte> bytes = test::readBytes(entry.path());
    bytes.back() ^= std::byte{1};
    test::writeBytes(entry.path(), bytes);
  }
  EXPECT_TRUE(sameBits(packedSkinTransfer(mesh, disk), computed));
  EXPECT_NE(test::inodeOf(entry), stored) << "the damaged entry was not replaced";
  EXPECT_TRUE(sameBits(packedSkinTransfer(mesh, DiskCache(std::filesystem::path())), computed));  // no cache
}
