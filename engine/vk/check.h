#pragma once
// Contract: every VkResult hairpipe receives goes through check(). A failure throws hp::Error whose
// message names the call and the VkResult (e.g. "vkAllocateMemory failed: VK_ERROR_OUT_OF_DEVICE_MEMORY").
#include "hairpipe_volk.h"

#include <cstdint>

namespace hp::vk {
const char* resultName(VkResult result);
void check(VkResult result, const char* call);
}  // namespace hp::vk

#define HP_VK_CHECK(expr) ::hp::vk::check((expr), #expr)
