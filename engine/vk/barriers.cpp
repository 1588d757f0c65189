#include "engine/vk/barriers.h"

#include <atomic>

#include "engine/vk/context.h"

namespace hp::vk {
namespace {
std::atomic<std::uint64_t> recordedBarriers{0};

void record(const Context& ctx, VkCommandBuffer cmd, const VkDependencyInfo& dep) {
  recordedBarriers.fetch_add(1, std::memory_order_relaxed);
  ctx.fn().vkCmdPipelineBarrier2(cmd, &dep);
}
struct Scope {
  VkPipelineStageFlags2 stage;
  VkAccessFlags2 access;
};

Scope bufferScope(BufferUse use) {
  switch (use) {
    case BufferUse::None: return {VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE};
    case BufferUse::TransferSrc: return {VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
    case BufferUse::TransferDst: return {VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT};
    case BufferUse::ComputeRead:
      return {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
              VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_UNIFORM_READ_BIT | VK_ACCESS_2_SHADER_SAMPLED_READ_BIT};
    case BufferUse::ComputeWrite:
      return {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                                                          VK_ACCESS_2_SHADER_SAMPLED_READ_BIT |
                                                          VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT};
    case BufferUse::VertexRead:
      return {VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_UNIFORM_READ_BIT};
    case BufferUse::FragmentRead:
      return {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_UNIFORM_READ_BIT};
    case BufferUse::GraphicsRead:
      return {VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
              VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_UNIFORM_READ_BIT};
    case BufferUse::HostRead: return {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT};
    case BufferUse::IndirectRead: return {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT};
  }
  return {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT};
}

struct ImageScope {
  VkPipelineStageFlags2 stage;
  VkAccessFlags2 access;
  VkImageLayout layout;
};

ImageScope imageScope(ImageUse use) {
  switch (use) {
    case ImageUse::Undefined: return {VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED};
    case ImageUse::TransferSrc:
      return {VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_RESOLVE_BIT | VK_PIPELINE_STAGE_2_BLIT_BIT,
              VK_ACCESS_2_TRANSFER_READ_BIT,
              VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
    case ImageUse::TransferDst:
      return {VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_CLEAR_BIT | VK_PIPELINE_STAGE_2_RESOLVE_BIT |
                  VK_PIPELINE_STAGE_2_BLIT_BIT,
              VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
    case ImageUse::ColorAttachment:
      return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
              VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
              VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    case ImageUse::DepthAttachment:
      return {VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
              VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};  // DEPTH_ATTACHMENT_OPTIMAL needs separateDepthStencilLayouts
    case ImageUse::FragmentSampled:
      return {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    case ImageUse::VertexSampled:
      return {VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    case ImageUse::ComputeSampled:
      return {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
              VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    case ImageUse::GraphicsSampled:
      return {VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT,
              VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    case ImageUse::ComputeStorageWrite:
      return {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_IMAGE_LAYOUT_GENERAL};
    case ImageUse::FragmentSampledDiscard:
      // Reads need only an execution dependency before the layout transition writes.
      return {VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED};
    case ImageUse::ColorAttachmentDiscard:
      // Earlier writes (and MSAA resolves) must finish before the transition overwrites the image.
      return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
              VK_IMAGE_LAYOUT_UNDEFINED};
    case ImageUse::DepthAttachmentDiscard:
      return {VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT, VK_IMAGE_LAYOUT_UNDEFINED};
    case ImageUse::SwapchainAcquired:
      // The stages at which the frame's submission waits on the acquire semaphore (kSwapchainWaitStages).
      return {kSwapchainWaitStages, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_UNDEFINED};
    case ImageUse::Present:
      return {VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR};
  }
  return {VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT,
          VK_IMAGE_LAYOUT_GENERAL};
}
}  // namespace

VkImageLayout imageLayout(ImageUse use) { return imageScope(use).layout; }

void bufferBarrier(const Context& ctx, VkCommandBuffer cmd, VkBuffer buffer, BufferUse from, BufferUse to,
                   VkDeviceSize offset, VkDeviceSize size) {
  Scope src = bufferScope(from), dst = bufferScope(to);
  VkBufferMemoryBarrier2 b{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
  b.srcStageMask = src.stage;
  b.srcAccessMask = src.access;
  b.dstStageMask = dst.stage;
  b.dstAccessMask = dst.access;
  b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.buffer = buffer;
  b.offset = offset;
  b.size = size;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.bufferMemoryBarrierCount = 1;
  dep.pBufferMemoryBarriers = &b;
  record(ctx, cmd, dep);
}

void memoryBarrier(const Context& ctx, VkCommandBuffer cmd, BufferUse from, BufferUse to) {
  Scope src = bufferScope(from), dst = bufferScope(to);
  VkMemoryBarrier2 b{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  b.srcStageMask = src.stage;
  b.srcAccessMask = src.access;
  b.dstStageMask = dst.stage;
  b.dstAccessMask = dst.access;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = 1;
  dep.pMemoryBarriers = &b;
  record(ctx, cmd, dep);
}

void executionBarrier(const Context& ctx, VkCommandBuffer cmd) {
  VkMemoryBarrier2 b{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  b.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  b.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = 1;
  dep.pMemoryBarriers = &b;
  record(ctx, cmd, dep);
}

void imageBarrier(const Context& ctx, VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, ImageUse from,
                  ImageUse to, std::uint32_t layers, std::uint32_t firstLayer) {
  ImageScope src = imageScope(from), dst = imageScope(to);
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = src.stage;
  b.srcAccessMask = src.access;
  b.dstStageMask = dst.stage;
  b.dstAccessMask = dst.access;
  b.oldLayout = src.layout;
  b.newLayout = dst.layout;
  b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {aspect, 0, 1, firstLayer, layers};
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &b;
  record(ctx, cmd, dep);
}

std::uint64_t barriersRecorded() { return recordedBarriers.load(std::memory_order_relaxed); }
}  // namespace hp::vk
