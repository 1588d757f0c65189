#include <gtest/gtest.h>

#include <random>

#include "engine/core/error.h"
#include "engine/vk/buffer_view.h"
#include "engine/vk/context.h"
#include "engine/vk/transfer.h"
#include "tests/support/vk_fixture.h"

using namespace hp::vk;
using hp::test::VulkanTest;

TEST_F(VulkanTest, LargeRandomBufferRoundTripsThroughDeviceMemory) {
  const std::size_t count = 8u << 20;  // 32 MiB of random words
  std::vector<std::uint32_t> data(count);
  std::mt19937 rng(1234);
  for (auto& v : data) v = rng();
  Buffer buffer(*ctx, count * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                MemoryKind::DeviceLocal, "round trip");
  upload<std::uint32_t>(*ctx, buffer, data, BufferUse::TransferSrc);
  auto back = readback<std::uint32_t>(*ctx, buffer, BufferUse::TransferSrc, count);
  ASSERT_EQ(back.size(), data.size());
  EXPECT_TRUE(back == data);
  // A partial readback at an offset returns that slice.
  auto bytes = readbackBytes(*ctx, buffer, BufferUse::TransferSrc, 400, 16);
  EXPECT_EQ(std::memcmp(bytes.data(), data.data() + 100, 16), 0);
}

TEST_F(VulkanTest, OverrunningTransfersAreRefused) {
  Buffer buffer(*ctx, 64, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                MemoryKind::DeviceLocal, "small");
  std::vector<std::uint32_t> tooMuch(17, 1u);
  EXPECT_THROW(upload<std::uint32_t>(*ctx, buffer, tooMuch, BufferUse::TransferSrc), hp::Error);
  EXPECT_THROW(readbackBytes(*ctx, buffer, BufferUse::None, 32, 64), hp::Error);
  EXPECT_THROW(readbackBytes(*ctx, buffer, BufferUse::None, 128), hp::Error);                  // offset past the end
  EXPECT_THROW(readbackBytes(*ctx, buffer, BufferUse::None, 16, ~VkDeviceSize(0) - 8), hp::Error);  // would wrap
  EXPECT_THROW(uploadBytes(*ctx, buffer, tooMuch.data(), 8, BufferUse::TransferSrc, ~VkDeviceSize(0) - 4), hp::Error);
  EXPECT_THROW(Buffer(*ctx, 0, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::DeviceLocal, "empty"), hp::Error);
}

// A texel buffer view covers its buffer's whole texels; formats hairpipe does not read through texel buffers
// and counts past the device's maxTexelBufferElements are refused by name.
TEST_F(VulkanTest, TexelBufferViewsTakeTheirFormatsAndRefuseTheRest) {
  Buffer buffer(*ctx, 72, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT,
                MemoryKind::DeviceLocal, "texels");
  const BufferView pairs(*ctx, buffer, VK_FORMAT_R32G32_UINT, "texels as pairs");  // 9 texels
  const BufferView quads(*ctx, buffer, VK_FORMAT_R32G32B32A32_SFLOAT, "texels as quads");  // 4, the rest left out
  EXPECT_TRUE(pairs && quads);
  EXPECT_EQ(texelBufferTexelBytes(VK_FORMAT_R32G32_UINT), 8u);
  EXPECT_EQ(texelBufferTexelBytes(VK_FORMAT_R32G32B32A32_SFLOAT), 16u);
  try {
    BufferView(*ctx, buffer, VK_FORMAT_R8_UNORM, "bytes");
    ADD_FAILURE() << "a format hairpipe does not read was taken";
  } catch (const hp::Error& e) {
    EXPECT_NE(std::string(e.what()).find("not one hairpipe reads"), std::string::npos) << e.what();
  }
  const std::uint64_t limit = ctx->properties().limits.maxTexelBufferElements;
  EXPECT_TRUE(texelBufferFits(*ctx, limit));
  EXPECT_FALSE(texelBufferFits(*ctx, limit + 1));
}
