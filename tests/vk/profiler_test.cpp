#include <gtest/gtest.h>

#include "engine/vk/profiler.h"
#include "shaders/embedded_shaders.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "tests/support/vk_fixture.h"

using namespace hp::vk;
using hp::test::VulkanTest;

TEST_F(VulkanTest, TimestampProfilerReturnsPositiveOrderedNestedTimes) {
  ASSERT_TRUE(ctx->timestampsSupported());
  GpuProfiler profiler(*ctx, 8, "test profiler");
  ASSERT_TRUE(profiler.supported());
  const VkDeviceSize size = 64ull << 20;
  Buffer a(*ctx, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::DeviceLocal, "a");
  Buffer b(*ctx, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::DeviceLocal, "b");
  submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    profiler.reset(cmd);
    profiler.begin(cmd, "outer");
    profiler.begin(cmd, "fill");
    ctx->fn().vkCmdFillBuffer(cmd, a.handle(), 0, size, 0x01020304u);
    profiler.end(cmd);
    bufferBarrier(*ctx, cmd, a.handle(), BufferUse::TransferDst, BufferUse::TransferSrc);
    profiler.begin(cmd, "copy");
    VkBufferCopy region{0, 0, size};
    ctx->fn().vkCmdCopyBuffer(cmd, a.handle(), b.handle(), 1, &region);
    profiler.end(cmd);
    profiler.end(cmd);
  }, "profiled work");
  auto times = profiler.results();
  ASSERT_EQ(times.size(), 3u);
  EXPECT_EQ(times[0].name, "outer");
  EXPECT_EQ(times[0].depth, 0);
  EXPECT_EQ(times[1].name, "fill");
  EXPECT_EQ(times[1].depth, 1);
  EXPECT_EQ(times[2].name, "copy");
  for (const auto& t : times) EXPECT_GT(t.milliseconds, 0.0) << t.name;
  // The outer scope contains both inner ones.
  EXPECT_GE(times[0].milliseconds, times[1].milliseconds + times[2].milliseconds * 0.99);
}

TEST(EmbeddedShaders, EveryShaderIsValidSpirvAndUnknownNamesAreRefused) {
  auto names = hp::shaders::names();
  ASSERT_FALSE(names.empty());
  for (const auto& name : names) {
    auto words = hp::shaders::spirv(name);
    ASSERT_GT(words.size(), 5u) << name;
    EXPECT_EQ(words[0], 0x07230203u) << name;  // SPIR-V magic
  }
  EXPECT_THROW(hp::shaders::spirv("no_such_shader.comp"), hp::Error);
}
