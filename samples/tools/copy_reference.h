#pragma once
// Contract: the bandwidth yardstick of the benchmarks: a device-local to device-local vkCmdCopyBuffer
// recorded as profiler scope "copy", so a pass's achieved bytes/s can be stated as a fraction of what
// the same device copies in the same run. The copy moves 2 x bytes (read + write). measureAlone() times it in
// submissions of its own, repeated until it is stable: the yardstick; the copy recorded inside a frame tells
// whether the device's timestamps resolve that frame's passes (lavapipe's do not: docs/PERFORMANCE.md).
#include <string>

#include "engine/vk/buffer.h"
#include "engine/vk/profiler.h"

namespace hp::vk {
struct CopyTiming {
  double medianMs = 0.0;   // GPU timestamps: over the last runs that agreed (all runs when they never did)
  double wallMs = 0.0;     // host wall time of a copy's submission (submit to fence), median over the same runs
  double emptyWallMs = 0.0;  // the same for an empty submission: what a submission costs without work
  std::uint32_t runs = 0;  // submissions made
  bool stable = false;     // the last CopyReference::kSettled runs agreed within 5% of their median
};

class CopyReference {
 public:
  CopyReference(const Context& ctx, VkDeviceSize bytes);
  void record(VkCommandBuffer cmd, GpuProfiler& profiler) const;
  double bytesMoved() const { return 2.0 * double(source_.size()); }
  static constexpr std::uint32_t kSettled = 5;
  // The copy alone, one blocking submission each, until kSettled runs in a row agree or maxRuns were made.
  CopyTiming measureAlone(std::uint32_t maxRuns = 30) const;

 private:
  const Context* ctx_;
  Buffer source_;
  Buffer destination_;
};

// Why this device's timestamps do not resolve the passes recorded beside a copy that read inSubmissionMs
// (empty: they do). They do when they time the copy alone (at least half of what its submission takes
// beyond an empty submission's wall time) and the copy among the passes reads within 2x of alone.
std::string timestampsUnresolvedBecause(const CopyTiming& alone, double inSubmissionMs);

double gigabytesPerSecond(double bytes, double milliseconds);
}  // namespace hp::vk
