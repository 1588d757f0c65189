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
#include "hairpipe_volk.h"

#include <cstdint>

#include <functional>
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

class OneShotBatch {
 public:
  OneShotBatch(const Context& ctx, std::string name);
  // Work not submitted (an exception unwound past the batch) is discarded, never submitted.
  ~OneShotBatch();
  OneShotBatch(const OneShotBatch&) = delete;
  OneShotBatch& operator=(const OneShotBatch&) = delete;

  void record(const std::function<void(VkCommandBuffer)>& record);
  void keep(Buffer&& staging) { kept_.push_back(std::move(staging)); }
  // One submission of everything recorded since the last one, waited on; a no-op when nothing was.
  void submit();
  std::uint32_t submissions() const { return submissions_; }

 private:
  void release();

  const Context& ctx_;
  std::string name_;
  OneShotBatch* outer_;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  std::vector<Buffer> kept_;
  std::uint32_t submissions_ = 0;
};
}  // namespace hp::vk
