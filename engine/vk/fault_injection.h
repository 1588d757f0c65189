#pragma once
// Contract: a test facility for the error paths no healthy driver takes. armFault() makes check() see
// `result` instead of the next success of the Vulkan call whose name starts with `call` (after `skip`
// such successes), as if the driver had returned it; one fault at a time, process-wide, disarmed once
// fired. Arm only calls that have completed their work when they return (vkWaitForFences,
// vkAllocateMemory...), so the state left behind is what a real failure of that call leaves. hairpipe's
// tests use it for VK_ERROR_DEVICE_LOST; an application may use it to exercise its own handling.
#include "hairpipe_volk.h"

#include <string>

namespace hp::vk {
void armFault(const std::string& call, VkResult result, int skip = 0);
void disarmFault();
bool faultArmed();
// What check() reports for `call` returning `actual`: the armed fault when it matches, else `actual`.
VkResult injectFault(const char* call, VkResult actual);
}  // namespace hp::vk
