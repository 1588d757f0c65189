#include "engine/vk/submit.h"

#include <utility>

#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp::vk {
namespace {
VkCommandBuffer beginOneShot(const Context& ctx, const std::string& name) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = ctx.transientPool();
  alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  HP_VK_CHECK(ctx.fn().vkAllocateCommandBuffers(ctx.device(), &alloc, &cmd));
  ctx.setName(VK_OBJECT_TYPE_COMMAND_BUFFER, reinterpret_cast<std::uint64_t>(cmd), name);
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VkResult r = ctx.fn().vkBeginCommandBuffer(cmd, &begin);
  if (r != VK_SUCCESS) ctx.fn().vkFreeCommandBuffers(ctx.device(), ctx.transientPool(), 1, &cmd);
  check(r, "vkBeginCommandBuffer");
  return cmd;
}

// Ends, submits and waits for `cmd`; frees it and its fence on every path.
void submitOneShot(const Context& ctx, VkCommandBuffer cmd, const std::string& name) {
  VkFence fence = VK_NULL_HANDLE;
  struct Free {
    const Context& ctx;
    VkCommandBuffer& cmd;
    VkFence& fence;
    ~Free() {
      if (fence) ctx.fn().vkDestroyFence(ctx.device(), fence, nullptr);
      if (cmd) ctx.fn().vkFreeCommandBuffers(ctx.device(), ctx.transientPool(), 1, &cmd);
    }
  } free{ctx, cmd, fence};
  HP_VK_CHECK(ctx.fn().vkEndCommandBuffer(cmd));
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  HP_VK_CHECK(ctx.fn().vkCreateFence(ctx.device(), &fenceInfo, nullptr, &fence));
  ctx.setName(VK_OBJECT_TYPE_FENCE, reinterpret_cast<std::uint64_t>(fence), name + " fence");
  VkCommandBufferSubmitInfo cmdInfo{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cmdInfo.commandBuffer = cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cmdInfo;
  HP_VK_CHECK(ctx.fn().vkQueueSubmit2(ctx.queue(), 1, &submit, fence));
  HP_VK_CHECK(ctx.fn().vkWaitForFences(ctx.device(), 1, &fence, VK_TRUE, UINT64_MAX));
}
}  // namespace

void submitAndWait(const Context& ctx, const std::function<void(VkCommandBuffer)>& record, const std::string& name) {
  if (OneShotBatch* batch = ctx.openBatch()) {
    batch->record(record);
    return;
  }
  VkCommandBuffer cmd = beginOneShot(ctx, name);
  try {
    record(cmd);
  } catch (...) {
    ctx.fn().vkFreeCommandBuffers(ctx.device(), ctx.transientPool(), 1, &cmd);
    throw;
  }
  submitOneShot(ctx, cmd, name);
}

void keepUntilSubmitted(const Context& ctx, Buffer&& staging) {
  if (OneShotBatch* batch = ctx.openBatch()) batch->keep(std::move(staging));
}

void submitOpenBatch(const Context& ctx) {
  if (OneShotBatch* batch = ctx.openBatch()) batch->submit();
}

OneShotBatch::OneShotBatch(const Context& ctx, std::string name)
    : ctx_(ctx), name_(std::move(name)), outer_(ctx.openBatch()) {
  ctx_.setOpenBatch(this);
}

OneShotBatch::~OneShotBatch() {
  release();
  ctx_.setOpenBatch(outer_);
}

void OneShotBatch::release() {
  if (cmd_) ctx_.fn().vkFreeCommandBuffers(ctx_.device(), ctx_.transientPool(), 1, &cmd_);
  cmd_ = VK_NULL_HANDLE;
  kept_.clear();
}

void OneShotBatch::record(const std::function<void(VkCommandBuffer)>& record) {
  if (!cmd_) cmd_ = beginOneShot(ctx_, name_);
  record(cmd_);
}

void OneShotBatch::submit() {
  if (!cmd_) return;
  VkCommandBuffer cmd = std::exchange(cmd_, VK_NULL_HANDLE);
  try {
    submitOneShot(ctx_, cmd, name_);
  } catch (...) {
    kept_.clear();
    throw;
  }
  kept_.clear();
  ++submissions_;
}
}  // namespace hp::vk
