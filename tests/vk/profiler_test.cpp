#include <gtest/gtest.h>

#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/core/error.h"
#include "engine/vk/image.h"
#include "engine/vk/profiler.h"
#include "shaders/embedded_shaders.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "tests/support/cli_runner.h"
#include "tests/support/color_pass.h"
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

// A scope times the work recorded inside it: at least half of what the work adds to its submission's host
// wall time (less 1 ms of host jitter; on a GPU the copy is far shorter than that). lavapipe, once a render
// pass has run, takes a stamp only at its next flush: without the profiler's barrier after each stamp this
// scope read 0.014 ms of a 7 ms copy.
TEST_F(VulkanTest, ProfilerScopeTimesTheWorkInsideIt) {
  GpuProfiler profiler(*ctx, 2, "test profiler", StampBarriers::OnCpuDevices);
  ASSERT_TRUE(profiler.supported());
  const VkDeviceSize size = 64ull << 20;
  Buffer a(*ctx, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::DeviceLocal, "a");
  Buffer b(*ctx, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::DeviceLocal, "b");
  Image target(*ctx, ImageDesc{16, 16, 1, VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT,
                               VK_SAMPLE_COUNT_1_BIT, "cleared target"});
  auto wallMs = [&](bool work) {
    const auto start = std::chrono::steady_clock::now();
    submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
      profiler.reset(cmd);
      // A render pass first, as a frame's head draw comes before its compute passes.
      imageBarrier(*ctx, cmd, target.handle(), target.aspect(), ImageUse::Undefined, ImageUse::ColorAttachment);
      hp::test::beginClearedColorPass(*ctx, cmd, target.view(), {16, 16}, {});
      profiler.beginInRendering(cmd, "in rendering");  // no barrier may go here: the fixture fails on one
      profiler.end(cmd);
      ctx->fn().vkCmdEndRendering(cmd);
      bufferBarrier(*ctx, cmd, b.handle(), BufferUse::TransferDst, BufferUse::TransferDst);  // the last run's copy
      profiler.begin(cmd, "copy");
      VkBufferCopy region{0, 0, size};
      if (work) ctx->fn().vkCmdCopyBuffer(cmd, a.handle(), b.handle(), 1, &region);
      profiler.end(cmd);
    }, work ? "profiled copy" : "empty scope");
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  };
  wallMs(true);  // first touch of the buffers' pages
  const double empty = wallMs(false), copied = wallMs(true);
  const auto times = profiler.results();
  ASSERT_EQ(times.size(), 2u);
  EXPECT_EQ(times[1].name, "copy");
  const double scopeMs = times[1].milliseconds;
  EXPECT_GE(scopeMs, 0.5 * (copied - empty) - 1.0) << "wall: " << copied << " ms copied, " << empty << " ms empty";
  EXPECT_GT(scopeMs, 0.0);
}

// A profiler adds barriers only when asked (the benchmarks) and only on a CPU device: one after each stamp.
// By default a profiled frame keeps its own barriers alone, for synchronization validation to check.
TEST_F(VulkanTest, AProfilerAddsBarriersOnlyWhenAsked) {
  const bool cpu = ctx->properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  for (StampBarriers barriers : {StampBarriers::None, StampBarriers::OnCpuDevices}) {
    GpuProfiler profiler(*ctx, 1, "test profiler", barriers);
    std::uint64_t recorded = 0;
    submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
      profiler.reset(cmd);
      const std::uint64_t before = barriersRecorded();
      profiler.begin(cmd, "empty");
      profiler.end(cmd);
      recorded = barriersRecorded() - before;
    }, "profiled nothing");
    EXPECT_EQ(recorded, barriers == StampBarriers::OnCpuDevices && cpu ? 2u : 0u);
  }
}

namespace {
// A shell command's exit status (-1 when it did not exit normally) and its stdout and stderr together.
struct SpirvValRun {
  int status = -1;
  std::string output;
};
SpirvValRun runSpirvVal(const std::string& arguments) {
  SpirvValRun r;
  FILE* pipe = ::popen(("spirv-val " + arguments + " 2>&1").c_str(), "r");
  if (pipe == nullptr) {
    r.output = "popen failed";
    return r;
  }
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) r.output.append(buffer, n);
  const int status = ::pclose(pipe);
  if (status != -1 && WIFEXITED(status)) r.status = WEXITSTATUS(status);
  return r;
}
}  // namespace

// Every embedded module passes spirv-val (SPIRV-Tools) for the environment glslc compiles them for
// (--target-env=vulkan1.3, shaders/CMakeLists.txt). spirv-val comes from the Debian package spirv-tools
// (the Makefile's PACKAGES); a missing spirv-val is a failure, never a skip.
TEST(EmbeddedShaders, EveryShaderIsValidSpirvAndUnknownNamesAreRefused) {
  const SpirvValRun version = runSpirvVal("--version");
  ASSERT_EQ(version.status, 0) << "spirv-val is needed to validate the embedded shaders (Debian package "
                                  "spirv-tools; `make deps` installs it): "
                               << version.output;
  auto names = hp::shaders::names();
  ASSERT_FALSE(names.empty());
  const std::filesystem::path dir = hp::test::freshTempPath("embedded_spirv");
  std::filesystem::create_directories(dir);
  for (const auto& name : names) {
    auto words = hp::shaders::spirv(name);
    ASSERT_GT(words.size(), 5u) << name;
    EXPECT_EQ(words[0], 0x07230203u) << name;  // SPIR-V magic
    const std::filesystem::path file = dir / (name + ".spv");
    {
      std::ofstream out(file, std::ios::binary);
      out.write(reinterpret_cast<const char*>(words.data()), std::streamsize(words.size_bytes()));
      ASSERT_TRUE(out.good()) << "cannot write " << file;
    }
    const SpirvValRun r = runSpirvVal("--target-env vulkan1.3 '" + file.string() + "'");
    EXPECT_EQ(r.status, 0) << name << " fails spirv-val --target-env vulkan1.3:\n" << r.output;
  }
  EXPECT_THROW(hp::shaders::spirv("no_such_shader.comp"), hp::Error);
}
