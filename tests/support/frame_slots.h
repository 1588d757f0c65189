#pragma once
// Contract: the application's side of frames in flight in a test: one command buffer and fence per slot;
// begin(slot) waits for that slot's last submission, submit(slot) submits without waiting, and the
// destructor waits for every pending one.
#include <vector>

#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp::test {
struct FrameSlots {
  const hp::vk::Context& ctx;
  VkCommandPool pool = VK_NULL_HANDLE;
  std::vector<VkCommandBuffer> cmds;
  std::vector<VkFence> fences;
  std::vector<bool> pending;

  FrameSlots(const hp::vk::Context& c, std::uint32_t count) : ctx(c), cmds(count), fences(count), pending(count) {
    VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pi.queueFamilyIndex = ctx.queueFamily();
    HP_VK_CHECK(vkCreateCommandPool(ctx.device(), &pi, nullptr, &pool));
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = pool;
    ai.commandBufferCount = count;
    HP_VK_CHECK(vkAllocateCommandBuffers(ctx.device(), &ai, cmds.data()));
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    for (VkFence& f : fences) HP_VK_CHECK(vkCreateFence(ctx.device(), &fi, nullptr, &f));
  }
  ~FrameSlots() {
    for (std::size_t i = 0; i < fences.size(); ++i) wait(i);
    for (VkFence f : fences) vkDestroyFence(ctx.device(), f, nullptr);
    vkDestroyCommandPool(ctx.device(), pool, nullptr);
  }
  void wait(std::size_t slot) {
    if (!pending[slot]) return;
    HP_VK_CHECK(vkWaitForFences(ctx.device(), 1, &fences[slot], VK_TRUE, UINT64_MAX));
    HP_VK_CHECK(vkResetFences(ctx.device(), 1, &fences[slot]));
    pending[slot] = false;
  }
  VkCommandBuffer begin(std::size_t slot) {
    wait(slot);
    VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    HP_VK_CHECK(vkBeginCommandBuffer(cmds[slot], &bi));
    return cmds[slot];
  }
  void submit(std::size_t slot) {
    HP_VK_CHECK(vkEndCommandBuffer(cmds[slot]));
    VkCommandBufferSubmitInfo ci{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    ci.commandBuffer = cmds[slot];
    VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    si.commandBufferInfoCount = 1;
    si.pCommandBufferInfos = &ci;
    HP_VK_CHECK(vkQueueSubmit2(ctx.queue(), 1, &si, fences[slot]));
    pending[slot] = true;
  }
};
}  // namespace hp::test
