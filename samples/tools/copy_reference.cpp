#include "samples/tools/copy_reference.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/submit.h"

namespace hp::vk {
namespace {
constexpr VkBufferUsageFlags kUsage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

// The median host wall time of `runs` empty submissions: what submitting and waiting costs without work.
double emptySubmissionMs(const Context& ctx, std::uint32_t runs) {
  std::vector<double> wall;
  for (std::uint32_t i = 0; i < runs; ++i) {
    const auto start = std::chrono::steady_clock::now();
    submitAndWait(ctx, [](VkCommandBuffer) {}, "empty submission");
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  return median(wall);
}
}  // namespace

CopyReference::CopyReference(const Context& ctx, VkDeviceSize bytes)
    : ctx_(&ctx),
      source_(ctx, bytes, kUsage, MemoryKind::DeviceLocal, "copy reference source"),
      destination_(ctx, bytes, kUsage, MemoryKind::DeviceLocal, "copy reference destination") {
  submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    ctx.fn().vkCmdFillBuffer(cmd, source_.handle(), 0, bytes, 0x3f800000u);  // touch every page before timing
    bufferBarrier(ctx, cmd, source_.handle(), BufferUse::TransferDst, BufferUse::TransferSrc);
  }, "copy reference fill");
}

void CopyReference::record(VkCommandBuffer cmd, GpuProfiler& profiler) const {
  // Earlier iterations wrote the destination: order those writes before this one.
  bufferBarrier(*ctx_, cmd, destination_.handle(), BufferUse::TransferDst, BufferUse::TransferDst);
  profiler.begin(cmd, "copy");
  VkBufferCopy region{0, 0, source_.size()};
  ctx_->fn().vkCmdCopyBuffer(cmd, source_.handle(), destination_.handle(), 1, &region);
  profiler.end(cmd);
}

CopyTiming CopyReference::measureAlone(std::uint32_t maxRuns) const {
  GpuProfiler profiler(*ctx_, 2, "copy alone");
  std::vector<double> ms, wall;
  CopyTiming t;
  while (t.runs < std::max(maxRuns, kSettled)) {
    const auto start = std::chrono::steady_clock::now();
    submitAndWait(*ctx_, [&](VkCommandBuffer cmd) {
      profiler.reset(cmd);
      record(cmd, profiler);
    }, "copy alone");
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    ++t.runs;
    ms.push_back(profiler.results().front().milliseconds);
    if (ms.size() < kSettled) continue;
    const std::vector<double> last(ms.end() - kSettled, ms.end());
    const auto [lo, hi] = std::minmax_element(last.begin(), last.end());
    t.medianMs = median(last);
    t.wallMs = median(std::vector<double>(wall.end() - kSettled, wall.end()));
    t.stable = *hi - *lo <= 0.05 * t.medianMs;
    if (t.stable) break;
  }
  if (!t.stable) {
    t.medianMs = median(ms);
    t.wallMs = median(wall);
  }
  t.emptyWallMs = emptySubmissionMs(*ctx_, kSettled);
  return t;
}

std::string timestampsUnresolvedBecause(const CopyTiming& alone, double inSubmissionMs) {
  // What the copy's submission takes beyond an empty one's is (about) the copy itself.
  const double executed = alone.wallMs - alone.emptyWallMs;
  char why[200] = "";
  if (!(alone.medianMs >= 0.5 * executed))
    std::snprintf(why, sizeof why,
                  "the copy alone reads %.3f ms by timestamps, while its submission takes %.3f ms more than an empty one",
                  alone.medianMs, executed);
  else if (!(inSubmissionMs >= 0.5 * alone.medianMs && inSubmissionMs <= 2.0 * alone.medianMs))
    std::snprintf(why, sizeof why, "the copy reads %.3f ms beside the passes, %.3f ms alone", inSubmissionMs,
                  alone.medianMs);
  return why;
}

double gigabytesPerSecond(double bytes, double milliseconds) {
  return milliseconds > 0.0 ? bytes / (milliseconds * 1e-3) / 1e9 : 0.0;
}
}  // namespace hp::vk
