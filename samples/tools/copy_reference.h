#pragma once
// Contract: the bandwidth yardstick of the benchmarks, so a pass's achieved bytes/s can be stated as a
// fraction of what the same device copies in the same run: a device-local to device-local vkCmdCopyBuffer
// (recorded in frames as profiler scope "copy") and a compute shader's copy of the same buffers
// (shaders/copy_reference.comp). A copy moves 2 x bytes (read + write). measureAlone() times each in
// submissions of its own, repeated until stable; the yardstick is the faster of the two (on an H100 the
// transfer copy reaches about a third of what the shader copy does: docs/PERFORMANCE.md). The transfer copy
// recorded inside a frame tells whether the device's timestamps resolve that frame's passes.
#include <memory>
#include <string>

#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/profiler.h"

namespace hp::vk {
// The transfer copy alone (medianMs ... stable), and the compute copy alone.
struct CopyTiming {
  double medianMs = 0.0;   // GPU timestamps: over the last runs that agreed (all runs when they never did)
  double wallMs = 0.0;     // host wall time of a copy's submission (submit to fence), median over the same runs
  double emptyWallMs = 0.0;  // the same for an empty submission: what a submission costs without work
  std::uint32_t runs = 0;  // submissions made
  bool stable = false;     // the last CopyReference::kSettled runs agreed within 5% of their median
  double bytes = 0.0;      // what the transfer copy moves (read + write)
  double computeMs = 0.0;      // the compute copy, as medianMs
  double computeBytes = 0.0;   // what it moves: the whole buffer, or what one binding can address
  std::uint32_t computeRuns = 0;
  bool computeStable = false;
};

class CopyReference {
 public:
  CopyReference(const Context& ctx, VkDeviceSize bytes);
  void record(VkCommandBuffer cmd, GpuProfiler& profiler) const;
  double bytesMoved() const { return 2.0 * double(source_.size()); }
  static constexpr std::uint32_t kSettled = 5;
  // Each copy alone, one blocking submission each, until kSettled runs in a row agree or maxRuns were made.
  CopyTiming measureAlone(std::uint32_t maxRuns = 30) const;

 private:
  void recordCompute(VkCommandBuffer cmd, GpuProfiler& profiler) const;
  const Context* ctx_;
  Buffer source_;
  Buffer destination_;
  VkDeviceSize computeBytes_ = 0;  // bytes the compute copy reads (at most maxStorageBufferRange)
  DescriptorSet computeSet_;
  ComputePipeline computeCopy_;
};

// The yardstick in GB/s: the faster of the two copies alone.
double copyGigabytesPerSecond(const CopyTiming& alone);

// Why this device's timestamps do not resolve the passes recorded beside a copy that read inSubmissionMs
// (empty: they do). They do when they time the copy alone (at least half of what its submission takes
// beyond an empty submission's wall time, or all but at most 1 ms of it and at least a tenth: a
// submission's fixed cost) and the copy among the passes reads within 2x of alone.
std::string timestampsUnresolvedBecause(const CopyTiming& alone, double inSubmissionMs);

double gigabytesPerSecond(double bytes, double milliseconds);
}  // namespace hp::vk
