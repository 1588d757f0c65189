// An engine that recreates its device (after a device loss, a settings change) creates and destroys
// hairpipe contexts many times in one process. Each cycle must work (NVIDIA 580 refused vkCreateInstance
// from the 30th instance on: headless contexts now share one instance) and give back what it took: file
// descriptors, threads, mappings and memory. The use is printed every 10 cycles so a failure on a new
// driver says what grew and at which cycle creation first failed.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "engine/core/error.h"
#include "engine/vk/buffer.h"
#include "engine/vk/context.h"
#include "engine/vk/instance_cache.h"
#include "engine/vk/validation_log.h"
#include "samples/tools/host/process_use.h"

namespace {
using hp::ProcessUse;
using hp::processUse;

// One cycle: a headless context with validation (as every test makes), a buffer on it, all destroyed; the
// log is read after the device is gone, so messages of vkDestroyDevice (objects left alive) count too.
void oneCycle(int cycle) {
  hp::vk::ContextOptions options;
  options.validation = true;
  options.appName = "hairpipe-context-cycles";
  auto ctx = hp::vk::Context::createHeadless(options);
  const std::shared_ptr<hp::vk::ValidationLog> log = ctx->sharedValidationLog();
  {
    hp::vk::Buffer buffer(*ctx, 1u << 20, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, hp::vk::MemoryKind::DeviceLocal,
                          "cycle buffer");
  }
  ctx.reset();
  ASSERT_TRUE(log->messages().empty()) << "cycle " << cycle << ": " << log->describeProblems();
}
}  // namespace

TEST(ContextCycles, AHundredContextsGiveBackWhatTheyTake) {
  constexpr int kCycles = 100, kSettled = 10;  // the first cycles may load libraries and caches for good
  std::vector<ProcessUse> use;
  oneCycle(-1);  // the process's validating instance exists from here on (it may already)
  const std::size_t instances = hp::vk::sharedInstanceCount();
  for (int cycle = 0; cycle < kCycles; ++cycle) {
    try {
      oneCycle(cycle);
    } catch (const hp::Error& e) {
      FAIL() << "context cycle " << cycle << " failed: " << e.what();
    }
    if (HasFatalFailure()) return;
    use.push_back(processUse());
    if (cycle % 10 == 0)  // so a driver that fails later still leaves a record of what grew until then
      std::printf("cycle %d: fds %ld threads %ld mappings %ld rss %llu KiB\n", cycle, use.back().fds,
                  use.back().threads, use.back().mappings, (unsigned long long)(use.back().residentBytes / 1024));
  }
  EXPECT_EQ(hp::vk::sharedInstanceCount(), instances) << "each context made its own instance";
  const ProcessUse& settled = use[kSettled - 1];
  const ProcessUse& last = use.back();
  EXPECT_LE(last.fds, settled.fds) << "file descriptors leak";
  EXPECT_LE(last.threads, settled.threads) << "threads leak";
  EXPECT_LE(last.mappings, settled.mappings + 8) << "mappings leak";
  // 90 more cycles: under 64 KiB a cycle (allocator slack), where a leaked device or instance costs MiBs.
  EXPECT_LE(last.residentBytes, settled.residentBytes + (kCycles - kSettled) * 64 * 1024) << "memory leaks";
}
