#pragma once
// Contract: the bandwidth yardstick of the benchmarks: a device-local to device-local vkCmdCopyBuffer
// recorded as profiler scope "copy", so a pass's achieved bytes/s can be stated as a fraction of what
// the same device copies in the same run. The copy moves 2 x bytes (read + write).
#include "engine/vk/buffer.h"
#include "engine/vk/profiler.h"

namespace hp::vk {
class CopyReference {
 public:
  CopyReference(const Context& ctx, VkDeviceSize bytes);
  void record(VkCommandBuffer cmd, GpuProfiler& profiler) const;
  double bytesMoved() const { return 2.0 * double(source_.size()); }

 private:
  const Context* ctx_;
  Buffer source_;
  Buffer destination_;
};

double gigabytesPerSecond(double bytes, double milliseconds);
}  // namespace hp::vk
