#pragma once
// Contract: every pipeline barrier in hairpipe goes through these helpers (synchronization2).
// A use is a small semantic enum; the one switch in barriers.cpp maps it to stage, access and (for
// images) layout, so a barrier reads as "from what to what" and cannot mismatch stage and access.
// The context gives the device's function table (cmd is one of its command buffers).
#include "hairpipe_volk.h"

#include <cstdint>

namespace hp::vk {
class Context;

enum class BufferUse {
  None,              // nothing before (first use in a submission)
  TransferSrc,
  TransferDst,
  ComputeRead,       // storage, uniform or texel-buffer read in a compute shader
  ComputeWrite,      // storage write in a compute shader (its reads, texel-buffer ones too, included)
  VertexRead,        // storage read in a vertex shader (vertex pulling)
  FragmentRead,      // storage/uniform read in a fragment shader
  GraphicsRead,      // vertex + fragment shader reads
  HostRead,          // mapped readback after the submission
  IndirectRead,      // indirect dispatch or draw arguments
};

enum class ImageUse {
  Undefined,         // contents may be discarded
  TransferSrc,
  TransferDst,
  ColorAttachment,   // written (and blended) as a color attachment
  DepthAttachment,   // depth test + write
  FragmentSampled,   // sampled in a fragment shader
  VertexSampled,     // sampled in a vertex shader
  ComputeSampled,    // sampled in a compute shader
  GraphicsSampled,   // sampled in vertex and fragment shaders
  ComputeStorageWrite,     // written as a storage image in a compute shader (layout GENERAL)
  FragmentSampledDiscard,  // sampled in a fragment shader by earlier work, contents now discarded
  ColorAttachmentDiscard,  // written as a colour attachment (or resolve target) by earlier work, now discarded
  DepthAttachmentDiscard,  // written as a depth attachment by earlier work, now discarded
                           // (layout UNDEFINED): reusing a frame's image waits for those reads
  SwapchainAcquired,       // a swapchain image just acquired, contents discarded: the first transfer or
                           // colour write waits (at those stages) on the acquire semaphore
  Present,                 // handed to vkQueuePresentKHR (the present waits on a semaphore, no access)
};

// The stages a frame's submission waits at for its swapchain image (ImageUse::SwapchainAcquired).
inline constexpr VkPipelineStageFlags2 kSwapchainWaitStages =
    VK_PIPELINE_STAGE_2_BLIT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT | VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;

// A buffer range barrier between two uses.
void bufferBarrier(const Context& ctx, VkCommandBuffer cmd, VkBuffer buffer, BufferUse from, BufferUse to,
                   VkDeviceSize offset = 0, VkDeviceSize size = VK_WHOLE_SIZE);
// A global memory barrier between two uses (all buffers); for chains of dependent compute passes.
void memoryBarrier(const Context& ctx, VkCommandBuffer cmd, BufferUse from, BufferUse to);
// A layout transition (and its memory dependency) of `layers` layers from `firstLayer`, of one mip.
void imageBarrier(const Context& ctx, VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, ImageUse from,
                  ImageUse to, std::uint32_t layers = 1, std::uint32_t firstLayer = 0);
// An execution dependency alone, every stage before it to every stage after it, no memory access. lavapipe
// takes a timestamp only when its queue next flushes (at a barrier), so a benchmark's GpuProfiler
// (StampBarriers::OnCpuDevices) records one after each stamp on CPU devices: otherwise a scope's stamps land
// after the work that follows them.
void executionBarrier(const Context& ctx, VkCommandBuffer cmd);
VkImageLayout imageLayout(ImageUse use);
// How many barriers the helpers above have recorded in this process (all contexts): the soak test's unit
// for the validation layer's per-barrier bookkeeping.
std::uint64_t barriersRecorded();
}  // namespace hp::vk
