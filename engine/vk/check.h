#pragma once
// Contract: every VkResult hairpipe receives goes through check(). A failure throws hp::Error whose
// message names the call and the VkResult (e.g. "vkAllocateMemory failed: VK_ERROR_OUT_OF_DEVICE_MEMORY").
// For VK_ERROR_DEVICE_LOST it throws DeviceLost, an hp::Error like any other to everyone but a caller
// able to start again on a new device (the viewer), which tells it apart by type.
#include "hairpipe_volk.h"

#include <cstdint>

#include "engine/core/error.h"

namespace hp::vk {
class DeviceLost : public Error {
 public:
  using Error::Error;
};

const char* resultName(VkResult result);
void check(VkResult result, const char* call);
}  // namespace hp::vk

#define HP_VK_CHECK(expr) ::hp::vk::check((expr), #expr)
