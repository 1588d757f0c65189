#include "samples/tools/copy_reference.h"

#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/submit.h"

namespace hp::vk {
namespace {
constexpr VkBufferUsageFlags kUsage = VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
}

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

double gigabytesPerSecond(double bytes, double milliseconds) {
  return milliseconds > 0.0 ? bytes / (milliseconds * 1e-3) / 1e9 : 0.0;
}
}  // namespace hp::vk
