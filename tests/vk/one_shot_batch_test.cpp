// vk::OneShotBatch: uploads recorded while a batch is open run in one submission at submit(); a readback
// inside the batch submits it first, so it sees every earlier upload.
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "tests/support/vk_fixture.h"

using namespace hp::vk;
using hp::test::VulkanTest;

namespace {
constexpr VkBufferUsageFlags kUsage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

std::vector<std::uint32_t> words(std::uint32_t first, std::size_t count) {
  std::vector<std::uint32_t> v(count);
  std::iota(v.begin(), v.end(), first);
  return v;
}
}  // namespace

TEST_F(VulkanTest, UploadsInAnOpenBatchRunInOneSubmission) {
  Buffer a(*ctx, 4096, kUsage, MemoryKind::DeviceLocal, "batch a");
  Buffer b(*ctx, 4096, kUsage, MemoryKind::DeviceLocal, "batch b");
  const auto dataA = words(7, 1024), dataB = words(90000, 1024);
  {
    OneShotBatch batch(*ctx, "batched uploads");
    EXPECT_EQ(ctx->openBatch(), &batch);
    upload<std::uint32_t>(*ctx, a, dataA, BufferUse::TransferSrc);
    upload<std::uint32_t>(*ctx, b, dataB, BufferUse::TransferSrc);
    EXPECT_EQ(batch.submissions(), 0u);
    batch.submit();
    EXPECT_EQ(batch.submissions(), 1u);
    batch.submit();  // nothing recorded since: no submission
    EXPECT_EQ(batch.submissions(), 1u);
  }
  EXPECT_EQ(ctx->openBatch(), nullptr);
  EXPECT_EQ(readback<std::uint32_t>(*ctx, a, BufferUse::TransferSrc, 1024), dataA);
  EXPECT_EQ(readback<std::uint32_t>(*ctx, b, BufferUse::TransferSrc, 1024), dataB);
}

TEST_F(VulkanTest, AReadbackInAnOpenBatchSeesTheEarlierUploads) {
  Buffer a(*ctx, 4096, kUsage, MemoryKind::DeviceLocal, "batch a");
  const auto data = words(3, 1024);
  OneShotBatch batch(*ctx, "upload then read");
  upload<std::uint32_t>(*ctx, a, data, BufferUse::TransferSrc);
  EXPECT_EQ(readback<std::uint32_t>(*ctx, a, BufferUse::TransferSrc, 1024), data);
  EXPECT_EQ(batch.submissions(), 1u);
}

TEST_F(VulkanTest, AnUnsubmittedBatchIsDiscardedNotSubmitted) {
  Buffer a(*ctx, 4096, kUsage, MemoryKind::DeviceLocal, "batch a");
  const auto first = words(1, 1024), second = words(5000, 1024);
  upload<std::uint32_t>(*ctx, a, first, BufferUse::TransferSrc);
  {
    OneShotBatch batch(*ctx, "abandoned");  // e.g. construction threw before submit()
    upload<std::uint32_t>(*ctx, a, second, BufferUse::TransferSrc);
  }
  EXPECT_EQ(readback<std::uint32_t>(*ctx, a, BufferUse::TransferSrc, 1024), first);
}
