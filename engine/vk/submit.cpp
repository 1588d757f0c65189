#include "engine/vk/submit.h"

#include <utility>

#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp::vk {
namespace {
// A primary command buffer, or a secondary one (outside any rendering) for a deferred batch.
VkCommandBuffer beginOneShot(const Context& ctx, const std::string& name,
                             VkCommandBufferLevel level = VK_COMMAND_BUFFER_LEVEL_PRIMARY) {
  VkCommandBufferAllocateInfo alloc{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  alloc.commandPool = ctx.transientPool();
  alloc.level = level;
  alloc.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  HP_VK_CHECK(ctx.fn().vkAllocateCommandBuffers(ctx.device(), &alloc, &cmd));
  ctx.setName(VK_OBJECT_TYPE_COMMAND_BUFFER, reinterpret_cast<std::uint64_t>(cmd), name);
  VkCommandBufferInheritanceInfo inheritance{VK_STRUCTURE_TYPE_COMMAND_BUFFER_INHERITANCE_INFO};
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  if (level == VK_COMMAND_BUFFER_LEVEL_SECONDARY) begin.pInheritanceInfo = &inheritance;
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

DeferredWork::DeferredWork(const Context& ctx, VkCommandBuffer cmd, std::vector<Buffer> kept)
    : ctx_(ctx), cmd_(cmd), kept_(std::move(kept)) {}

DeferredWork::~DeferredWork() { ctx_.fn().vkFreeCommandBuffers(ctx_.device(), ctx_.transientPool(), 1, &cmd_); }

OneShotBatch::OneShotBatch(const Context& ctx, std::string name, Mode mode)
    : ctx_(ctx), name_(std::move(name)), mode_(mode), outer_(ctx.openBatch()) {
  if (!outer_) ctx_.setOpenBatch(this);  // inside another batch, work goes to the outer one
}

OneShotBatch::~OneShotBatch() {
  release();
  if (!outer_) ctx_.setOpenBatch(nullptr);
}

void OneShotBatch::release() {
  if (cmd_) ctx_.fn().vkFreeCommandBuffers(ctx_.device(), ctx_.transientPool(), 1, &cmd_);
  cmd_ = VK_NULL_HANDLE;
  kept_.clear();
}

void OneShotBatch::record(const std::function<void(VkCommandBuffer)>& record) {
  if (outer_) return outer_->record(record);
  if (!cmd_)
    cmd_ = beginOneShot(ctx_, name_,
                        mode_ == Mode::Defer ? VK_COMMAND_BUFFER_LEVEL_SECONDARY : VK_COMMAND_BUFFER_LEVEL_PRIMARY);
  record(cmd_);
}

std::shared_ptr<DeferredWork> OneShotBatch::take() {
  if (outer_ || mode_ != Mode::Defer || !cmd_) return nullptr;
  VkCommandBuffer cmd = std::exchange(cmd_, VK_NULL_HANDLE);
  auto work = std::make_shared<DeferredWork>(ctx_, cmd, std::move(kept_));  // frees cmd from here on
  kept_.clear();
  HP_VK_CHECK(ctx_.fn().vkEndCommandBuffer(cmd));
  return work;
}

void OneShotBatch::submit() {
  if (outer_) return;  // the outer batch submits
  if (mode_ == Mode::Defer)
    throw Error("'" + name_ + "': this work needs a queue submission (a readback), which a setter in the frame "
                "loop does not make");
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
