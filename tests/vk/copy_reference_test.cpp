// The benchmarks' copy yardstick (samples/tools/copy_reference.h) under the validation layer with
// synchronization validation (the fixture fails on any message: the shader copy's buffers, descriptors
// and pipeline, the transfer copy recorded twice in one submission as a frame records it): both copies
// timed alone settle into positive times over the whole buffer, and the yardstick is the faster.
#include <gtest/gtest.h>

#include <algorithm>

#include "engine/vk/submit.h"
#include "samples/tools/copy_reference.h"
#include "tests/support/vk_fixture.h"

using namespace hp::vk;
using hp::test::VulkanTest;

TEST_F(VulkanTest, CopyYardstickTimesBothCopiesWithoutAHazard) {
  const VkDeviceSize bytes = 8ull << 20;
  CopyReference copy(*ctx, bytes);
  GpuProfiler profiler(*ctx, 4, "copy in a frame");
  submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    profiler.reset(cmd);
    copy.record(cmd, profiler);
    copy.record(cmd, profiler);  // twice: the second orders its writes after the first's
  }, "copy in a frame");
  const CopyTiming t = copy.measureAlone(8);
  EXPECT_GE(t.runs, CopyReference::kSettled);
  EXPECT_GE(t.computeRuns, CopyReference::kSettled);
  EXPECT_GT(t.medianMs, 0.0);
  EXPECT_GT(t.computeMs, 0.0);
  EXPECT_EQ(t.bytes, 2.0 * double(bytes));
  EXPECT_EQ(t.computeBytes, 2.0 * double(bytes));  // 8 MiB is within every device's storage range
  const double transfer = gigabytesPerSecond(t.bytes, t.medianMs), shader = gigabytesPerSecond(t.computeBytes, t.computeMs);
  EXPECT_DOUBLE_EQ(copyGigabytesPerSecond(t), std::max(transfer, shader));
}

// When the timestamps resolve the passes, from the copy's timings alone (no device): lavapipe before its
// stamps were fenced read 0.014 ms of a 7 ms copy; an H100 reads 0.16 ms of a copy whose submission takes
// 0.48 ms more than an empty one (a fixed cost, not missed work); an honest CPU device reads what it took.
TEST(CopyYardstick, TimestampsResolveUnlessTheyMissMostOfTheCopy) {
  const auto timing = [](double stamped, double wall, double emptyWall) {
    CopyTiming t;
    t.medianMs = stamped;
    t.wallMs = wall;
    t.emptyWallMs = emptyWall;
    return t;
  };
  EXPECT_NE(timestampsUnresolvedBecause(timing(0.014, 7.2, 0.2), 0.014), "");       // lavapipe, unfenced stamps
  EXPECT_EQ(timestampsUnresolvedBecause(timing(0.164, 0.52, 0.044), 0.163), "");    // H100
  EXPECT_EQ(timestampsUnresolvedBecause(timing(6.9, 7.4, 0.2), 7.1), "");           // lavapipe, fenced stamps
  EXPECT_NE(timestampsUnresolvedBecause(timing(0.5, 3.2, 0.2), 0.5), "");           // 2.5 ms unstamped
  EXPECT_NE(timestampsUnresolvedBecause(timing(0.164, 0.52, 0.044), 0.02), "");     // beside the passes: 8x less
  EXPECT_NE(timestampsUnresolvedBecause(timing(0.02, 0.52, 0.044), 0.02), "");      // a fast device, unfenced
  EXPECT_NE(timestampsUnresolvedBecause(timing(0.0, 0.52, 0.044), 0.0), "");        // stamps that read nothing
}
