#include "samples/tools/copy_reference.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/submit.h"
#include "shaders/shared/copy_reference.h"

namespace hp::vk {
namespace {
constexpr VkBufferUsageFlags kUsage =
    VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
const Binding kCopyBindings[] = {
    {gpu::COPY_BINDING_SOURCE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::COPY_BINDING_DESTINATION, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
};

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

// Times `record` (one profiler scope) in blocking submissions of its own until kSettled runs in a row agree
// within 5% or `maxRuns` were made: the median of those runs (of all runs when they never agreed), their
// median wall time, the runs made and whether they settled.
struct Settled {
  double ms = 0.0, wallMs = 0.0;
  std::uint32_t runs = 0;
  bool stable = false;
};
template <class Record>
Settled timeUntilSettled(const Context& ctx, std::uint32_t maxRuns, std::uint32_t settled, const char* name,
                         Record record) {
  GpuProfiler profiler(ctx, 2, name, StampBarriers::OnCpuDevices);
  std::vector<double> ms, wall;
  Settled t;
  while (t.runs < std::max(maxRuns, settled)) {
    const auto start = std::chrono::steady_clock::now();
    submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      profiler.reset(cmd);
      record(cmd, profiler);
    }, name);
    wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    ++t.runs;
    ms.push_back(profiler.results().front().milliseconds);
    if (ms.size() < settled) continue;
    const std::vector<double> last(ms.end() - settled, ms.end());
    const auto [lo, hi] = std::minmax_element(last.begin(), last.end());
    t.ms = median(last);
    t.wallMs = median(std::vector<double>(wall.end() - settled, wall.end()));
    t.stable = *hi - *lo <= 0.05 * t.ms;
    if (t.stable) return t;
  }
  t.ms = median(ms);
  t.wallMs = median(wall);
  return t;
}
}  // namespace

CopyReference::CopyReference(const Context& ctx, VkDeviceSize bytes)
    : ctx_(&ctx),
      source_(ctx, bytes, kUsage, MemoryKind::DeviceLocal, "copy reference source"),
      destination_(ctx, bytes, kUsage, MemoryKind::DeviceLocal, "copy reference destination"),
      computeBytes_(std::min<VkDeviceSize>(bytes, ctx.properties().limits.maxStorageBufferRange) / 16 * 16),
      computeSet_(ctx, kCopyBindings, "copy reference compute"),
      computeCopy_(ctx, "copy_reference.comp", gpu::COPY_WORKGROUP_SIZE, {computeSet_.layout()}, sizeof(gpu::CopyPush),
                   "copy reference compute") {
  computeSet_.writeBuffer(gpu::COPY_BINDING_SOURCE, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, source_.handle(), 0, computeBytes_);
  computeSet_.writeBuffer(gpu::COPY_BINDING_DESTINATION, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, destination_.handle(), 0,
                          computeBytes_);
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

void CopyReference::recordCompute(VkCommandBuffer cmd, GpuProfiler& profiler) const {
  // The previous run's writes (a transfer copy or this) before this run's.
  memoryBarrier(*ctx_, cmd, BufferUse::TransferDst, BufferUse::ComputeWrite);
  memoryBarrier(*ctx_, cmd, BufferUse::ComputeWrite, BufferUse::ComputeWrite);
  bufferBarrier(*ctx_, cmd, source_.handle(), BufferUse::TransferSrc, BufferUse::ComputeRead);
  profiler.begin(cmd, "compute copy");
  const gpu::CopyPush push{std::uint32_t(computeBytes_ / 16)};
  computeCopy_.bind(cmd, computeSet_.set());
  computeCopy_.push(cmd, push);
  computeCopy_.dispatch(cmd, push.count);
  profiler.end(cmd);
  // The transfer copy that may follow reads the source and writes the destination again.
  bufferBarrier(*ctx_, cmd, source_.handle(), BufferUse::ComputeRead, BufferUse::TransferSrc);
  memoryBarrier(*ctx_, cmd, BufferUse::ComputeWrite, BufferUse::TransferDst);
}

CopyTiming CopyReference::measureAlone(std::uint32_t maxRuns) const {
  CopyTiming t;
  const Settled transfer = timeUntilSettled(*ctx_, maxRuns, kSettled, "copy alone",
                                            [&](VkCommandBuffer cmd, GpuProfiler& p) { record(cmd, p); });
  t.medianMs = transfer.ms;
  t.wallMs = transfer.wallMs;
  t.runs = transfer.runs;
  t.stable = transfer.stable;
  t.bytes = bytesMoved();
  const Settled compute = timeUntilSettled(*ctx_, maxRuns, kSettled, "compute copy alone",
                                           [&](VkCommandBuffer cmd, GpuProfiler& p) { recordCompute(cmd, p); });
  t.computeMs = compute.ms;
  t.computeRuns = compute.runs;
  t.computeStable = compute.stable;
  t.computeBytes = 2.0 * double(computeBytes_);
  t.emptyWallMs = emptySubmissionMs(*ctx_, kSettled);
  return t;
}

double copyGigabytesPerSecond(const CopyTiming& alone) {
  return std::max(gigabytesPerSecond(alone.bytes, alone.medianMs), gigabytesPerSecond(alone.computeBytes, alone.computeMs));
}

std::string timestampsUnresolvedBecause(const CopyTiming& alone, double inSubmissionMs) {
  // What the copy's submission takes beyond an empty one's is the copy itself plus a fixed cost of a
  // submission with work (its stamps and barriers, a GPU's clocks waking: 0.24-0.31 ms on an H100, whose
  // 64 MiB copy reads 0.16 ms), so up to kSubmissionSlackMs of it may go unstamped, as long as the stamps
  // still read a tenth of it (stamps that read nothing, or next to nothing, never pass).
  constexpr double kSubmissionSlackMs = 1.0;
  const double executed = alone.wallMs - alone.emptyWallMs;
  const bool slack = executed - alone.medianMs <= kSubmissionSlackMs && alone.medianMs >= 0.1 * executed;
  char why[200] = "";
  if (!(alone.medianMs >= 0.5 * executed || slack))
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
