// The memory pool: buffers and images share a few device allocations, at their alignment, without
// overlapping; a block goes back to the driver with its last allocation; and a hair instance costs a
// small constant number of vkAllocateMemory calls (counted through the device function table, the only
// way hairpipe reaches the driver) and of descriptor pools (shared, 256 sets each).
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

#include "compute/renderer/renderer.h"
#include "engine/vk/buffer.h"
#include "engine/vk/image.h"
#include "tests/support/small_frame.h"
#include "tests/support/device_call_counter.h"
#include "tests/support/vk_fixture.h"

using hp::test::VulkanTest;


TEST_F(VulkanTest, BuffersAndImagesShareAFewAllocationsWithoutOverlapping) {
  hp::vk::MemoryPool& pool = ctx->memoryPool();
  const std::size_t blocksBefore = pool.blocksHeld();
  std::vector<hp::vk::Buffer> buffers;
  std::vector<hp::vk::Image> images;
  {
    hp::test::DeviceCallCounter counter(*ctx);
    for (int i = 0; i < 200; ++i)
      buffers.emplace_back(*ctx, 1000 + 37 * i, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, hp::vk::MemoryKind::DeviceLocal,
                           "pool test buffer " + std::to_string(i));
    for (int i = 0; i < 8; ++i) {
      hp::vk::ImageDesc d;
      d.width = 64 + i;
      d.height = 32;
      d.format = VK_FORMAT_R8G8B8A8_UNORM;
      d.usage = VK_IMAGE_USAGE_SAMPLED_BIT;
      d.name = "pool test image " + std::to_string(i);
      images.emplace_back(*ctx, d);
    }
    // 200 buffers and 8 images: one block of buffers and one of images (more only where the driver asks
    // for dedicated memory, which it does not for these).
    EXPECT_LE(counter.calls().allocations, 2u);
  }
  // Per block, the buffers' ranges (as bound) do not overlap and sit at their alignment.
  std::map<VkDeviceMemory, std::vector<std::pair<VkDeviceSize, VkDeviceSize>>> ranges;
  for (const hp::vk::Buffer& b : buffers) {
    VkMemoryRequirements req;
    ctx->fn().vkGetBufferMemoryRequirements(ctx->device(), b.handle(), &req);
    const hp::vk::MemoryAllocation& a = b.allocation();
    EXPECT_EQ(a.offset % req.alignment, 0u) << b.name();
    ranges[a.memory].push_back({a.offset, a.offset + req.size});
  }
  for (auto& [memory, list] : ranges) {
    std::sort(list.begin(), list.end());
    for (std::size_t i = 1; i < list.size(); ++i) EXPECT_LE(list[i - 1].second, list[i].first);
  }
  EXPECT_GT(pool.blocksHeld(), blocksBefore);
  buffers.clear();
  images.clear();
  EXPECT_EQ(pool.blocksHeld(), blocksBefore) << "empty blocks go back to the driver";
}

TEST_F(VulkanTest, AHairInstanceCostsAFewDeviceAllocationsAndDescriptorPools) {
  hp::RendererSettings settings;
  settings.formats = {VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_1_BIT};
  hp::Renderer renderer(*ctx, settings);
  const hp::HairAsset asset = hp::test::defaultHeadWithStrands(3000);
  auto first = renderer.createInstance(asset, {});
  const std::uint64_t poolsBefore = ctx->descriptorPools().poolsCreated();
  hp::test::DeviceCallCounter counter(*ctx);
  std::vector<std::unique_ptr<hp::HairInstance>> more;
  for (int i = 0; i < 4; ++i) more.push_back(renderer.createInstance(asset, {}));
  // Each instance holds ~40 buffers (was one vkAllocateMemory each): now they fill the pool's blocks.
  const std::uint64_t pools = ctx->descriptorPools().poolsCreated() - poolsBefore;
  std::cout << "for 4 more instances: " << counter.calls().allocations << " vkAllocateMemory calls, " << pools
            << " descriptor pools\n";
  EXPECT_LE(counter.calls().allocations, 4u);
  EXPECT_LE(pools, 1u);  // ~30 sets each (was one pool per set) share pools of 256
  more.clear();
  first.reset();
}
