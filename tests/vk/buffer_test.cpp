#include <gtest/gtest.h>

#include <random>

#include "engine/core/error.h"
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
