#include "engine/vk/submit.h"

#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp::vk {
namespace {
// Frees the command buffer and fence on every path, including a throwing record callback.
struct OneShot {
  const Context& ctx;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  ~OneShot() {
    if (fence) ctx.fn().vkDestroyFence(ctx.device(), fence, nullptr);
    if (cmd) ctx.fn().vkFreeCommandBuffers(ctx.device(), ctx.transientPool(), 1, &cmd);
  }
};
}  // namespace

void submitAndWait(const Context& ctx, const std::function<void(VkCommandBuffer)>& record, const std::string& name) {
  OneShot shot{ctx};
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = ctx.transientPool();
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  HP_VK_CHECK(ctx.fn().vkAllocateCommandBuffers(ctx.device(), &alloc, &shot.cmd));
  ctx.setName(VK_OBJECT_TYPE_COMMAND_BUFFER, reinterpret_cast<std::uint64_t>(shot.cmd), name);
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  HP_VK_CHECK(ctx.fn().vkBeginCommandBuffer(shot.cmd, &begin));
  record(shot.cmd);
  HP_VK_CHECK(ctx.fn().vkEndCommandBuffer(shot.cmd));

  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  HP_VK_CHECK(ctx.fn().vkCreateFence(ctx.device(), &fenceInfo, nullptr, &shot.fence));
  ctx.setName(VK_OBJECT_TYPE_FENCE, reinterpret_cast<std::uint64_t>(shot.fence), name + " fence");
  VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmdInfo.commandBuffer = shot.cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmdInfo;
  HP_VK_CHECK(ctx.fn().vkQueueSubmit2(ctx.queue(), 1, &submit, shot.fence));
  HP_VK_CHECK(ctx.fn().vkWaitForFences(ctx.device(), 1, &shot.fence, VK_TRUE, UINT64_MAX));
}
}  // namespace hp::vk
