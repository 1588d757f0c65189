// A multi-level inclusive prefix sum over 1M random words on the device, checked against the CPU.
// Exercises compute pipelines, descriptor sets, push constants, 2D-folded dispatch and barriers.
#include <gtest/gtest.h>

#include <random>

#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "shaders/shared/selftest.h"
#include "tests/support/vk_fixture.h"

using namespace hp::vk;
using hp::test::VulkanTest;

namespace {
constexpr VkBufferUsageFlags kScanBufferUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
const std::uint32_t kBlock = hp::gpu::SCAN_WORKGROUP_SIZE;

// One level of the scan: its data, the per-block totals, and a descriptor set binding both.
struct Level {
  std::uint32_t count;
  Buffer sums;
  DescriptorSet set;
};

const Binding kBindings[] = {
    {hp::gpu::SCAN_BINDING_DATA, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {hp::gpu::SCAN_BINDING_SUMS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
};
}  // namespace

TEST_F(VulkanTest, InclusivePrefixSumOfOneMillionWordsMatchesCpu) {
  const std::uint32_t n = 1u << 20;
  std::vector<std::uint32_t> input(n);
  std::mt19937 rng(42);
  for (auto& v : input) v = rng() & 0xFFFF;

  Buffer data(*ctx, n * 4ull, kScanBufferUsage, MemoryKind::DeviceLocal, "scan data");
  upload<std::uint32_t>(*ctx, data, input, BufferUse::ComputeWrite);

  std::vector<Level> levels;
  VkBuffer levelData = data.handle();
  for (std::uint32_t count = n; count > 1; count = (count + kBlock - 1) / kBlock) {
    std::uint32_t blocks = (count + kBlock - 1) / kBlock;
    Level level{count, Buffer(*ctx, blocks * 4ull, kScanBufferUsage, MemoryKind::DeviceLocal, "scan sums"),
                DescriptorSet(*ctx, kBindings, "scan level")};
    level.set.writeStorageBuffer(hp::gpu::SCAN_BINDING_DATA, levelData);
    level.set.writeStorageBuffer(hp::gpu::SCAN_BINDING_SUMS, level.sums.handle());
    levelData = level.sums.handle();
    levels.push_back(std::move(level));
  }
  ASSERT_EQ(levels.size(), 3u);

  ComputePipeline scan(*ctx, "selftest_scan_blocks.comp", kBlock, {levels[0].set.layout()},
                       sizeof(hp::gpu::ScanPush), "scan blocks");
  ComputePipeline add(*ctx, "selftest_scan_add.comp", kBlock, {levels[0].set.layout()},
                      sizeof(hp::gpu::ScanPush), "scan add");
  submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    for (const Level& level : levels) {  // down: scan blocks, totals go one level up
      scan.bind(cmd, level.set.set());
      scan.push(cmd, hp::gpu::ScanPush{level.count});
      scan.dispatch(cmd, level.count);
      memoryBarrier(*ctx, cmd, BufferUse::ComputeWrite, BufferUse::ComputeWrite);
    }
    for (auto it = levels.rbegin(); it != levels.rend(); ++it) {  // up: add scanned totals of earlier blocks
      add.bind(cmd, it->set.set());
      add.push(cmd, hp::gpu::ScanPush{it->count});
      add.dispatch(cmd, it->count);
      memoryBarrier(*ctx, cmd, BufferUse::ComputeWrite, BufferUse::ComputeWrite);
    }
  }, "prefix sum");

  auto result = readback<std::uint32_t>(*ctx, data, BufferUse::ComputeWrite, n);
  std::uint32_t running = 0;
  std::size_t mismatches = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    running += input[i];
    mismatches += result[i] != running;
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_EQ(result.back(), running);
}
