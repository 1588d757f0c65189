#pragma once
// Contract: one-shot work outside the frame loop (uploads, readbacks, LUT builds, tests). The callback
// records into a fresh primary command buffer; the submission is waited on with a fence before return,
// so everything it touched is free to reuse or destroy. Never used inside a frame the app records.
//
// OneShotBatch: while one is open on a context, submitAndWait records into the batch's command buffer
// instead (in call order) and returns at once; the work runs at submit(), in one submission. What the
// recorded work reads (staging buffers) is handed to keepUntilSubmitted(). Readbacks submit the batch
// first (they need the results). Object construction (Renderer, createInstance) opens one, so its
// uploads cost one submission and one wait. A context is used by one thread at a time (its command
// pool is not externally synchronized), so the open batch is per context.
//
// A deferred batch (OneShotBatch::Mode::Defer) records into a secondary command buffer and never submits:
// take() hands the recorded work over (DeferredWork), for the caller to execute inside a command buffer of
// a later frame (vkCmdExecuteCommands, outside any rendering) and to destroy once that frame is done. So a
// setter in the frame loop costs the application's queue no submission and no wait. A readback needs a
// submission: inside a deferred batch it throws hp::Error. A batch opened inside another records into the
// outer one (whose mode and submission rule).
#include "hairpipe_volk.h"

#include <cstdint>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "engine/vk/buffer.h"

namespace hp::vk {
class Context;
void submitAndWait(const Context& ctx, const std::function<void(VkCommandBuffer)>& record, const std::string& name);
// Keeps `staging` alive until the open batch's submission completes; without a batch it is freed now.
void keepUntilSubmitted(const Context& ctx, Buffer&& staging);
// Submits the context's open batch, if any, and waits for it (before reading results on the host).
void submitOpenBatch(const Context& ctx);

// Work recorded by a deferred batch: a secondary command buffer and the staging buffers it reads. Freed
// on destruction (after the frame that executed it is complete).
class DeferredWork {
 public:
  DeferredWork(const Context& ctx, VkCommandBuffer cmd, std::vector<Buffer> kept);
  ~DeferredWork();
  DeferredWork(const DeferredWork&) = delete;
  DeferredWork& operator=(const DeferredWork&) = delete;
  VkCommandBuffer commandBuffer() const { return cmd_; }

 private:
  const Context& ctx_;
  VkCommandBuffer cmd_;
  std::vector<Buffer> kept_;
};

class OneShotBatch {
 public:
  enum class Mode { Submit, Defer };
  OneShotBatch(const Context& ctx, std::string name, Mode mode = Mode::Submit);
  // Work not submitted (an exception unwound past the batch) is discarded, never submitted.
  ~OneShotBatch();
  OneShotBatch(const OneShotBatch&) = delete;
  OneShotBatch& operator=(const OneShotBatch&) = delete;

  void record(const std::function<void(VkCommandBuffer)>& record);
  void keep(Buffer&& staging) {
    if (outer_)
      outer_->keep(std::move(staging));
    else
      kept_.push_back(std::move(staging));
  }
  // One submission of everything recorded since the last one, waited on; a no-op when nothing was.
  // A deferred batch throws hp::Error instead.
  void submit();
  std::uint32_t submissions() const { return submissions_; }
  // Defer: the work recorded so far (null when none), ended and handed over; the batch starts empty.
  std::shared_ptr<DeferredWork> take();

 private:
  void release();

  const Context& ctx_;
  std::string name_;
  Mode mode_;
  OneShotBatch* outer_;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  std::vector<Buffer> kept_;
  std::uint32_t submissions_ = 0;
};
}  // namespace hp::vk
