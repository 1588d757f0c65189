#pragma once
// Contract: one-shot work outside the frame loop (uploads, readbacks, LUT builds, tests). The callback
// records into a fresh primary command buffer; the submission is waited on with a fence before return,
// so everything it touched is free to reuse or destroy. Never used inside a frame the app records.
#include <volk.h>

#include <cstdint>

#include <functional>
#include <string>

namespace hp::vk {
class Context;
void submitAndWait(const Context& ctx, const std::function<void(VkCommandBuffer)>& record, const std::string& name);
}  // namespace hp::vk
