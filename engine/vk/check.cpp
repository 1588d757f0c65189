#include "engine/vk/check.h"

#include <cctype>
#include <string>

#include "engine/core/error.h"
#include "engine/vk/fault_injection.h"

namespace hp::vk {
const char* resultName(VkResult result) {
  switch (result) {
#define HP_RESULT_CASE(r) \
  case r:                 \
    return #r;
    HP_RESULT_CASE(VK_SUCCESS)
    HP_RESULT_CASE(VK_NOT_READY)
    HP_RESULT_CASE(VK_TIMEOUT)
    HP_RESULT_CASE(VK_EVENT_SET)
    HP_RESULT_CASE(VK_EVENT_RESET)
    HP_RESULT_CASE(VK_INCOMPLETE)
    HP_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
    HP_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    HP_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
    HP_RESULT_CASE(VK_ERROR_DEVICE_LOST)
    HP_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
    HP_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
    HP_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
    HP_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
    HP_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
    HP_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
    HP_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
    HP_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL)
    HP_RESULT_CASE(VK_ERROR_UNKNOWN)
    HP_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
    HP_RESULT_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    HP_RESULT_CASE(VK_ERROR_FRAGMENTATION)
    HP_RESULT_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    HP_RESULT_CASE(VK_PIPELINE_COMPILE_REQUIRED)
    HP_RESULT_CASE(VK_ERROR_SURFACE_LOST_KHR)
    HP_RESULT_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
    HP_RESULT_CASE(VK_SUBOPTIMAL_KHR)
    HP_RESULT_CASE(VK_ERROR_OUT_OF_DATE_KHR)
    HP_RESULT_CASE(VK_ERROR_VALIDATION_FAILED_EXT)
#undef HP_RESULT_CASE
    default:
      return "VK_RESULT_UNKNOWN";
  }
}

namespace {
// "ctx.fn().vkWaitForFences(...)" -> "vkWaitForFences(...)": device calls go through the context's table,
// and errors (and injected faults) name the Vulkan function, not the expression that reached it.
const char* vulkanCall(const char* call) {
  for (const char* p = call; p[0] && p[1]; ++p)
    if (p[0] == 'v' && p[1] == 'k' && std::isupper(static_cast<unsigned char>(p[2]))) return p;
  return call;
}
}  // namespace

void check(VkResult result, const char* expression) {
  const char* call = vulkanCall(expression);
  result = injectFault(call, result);
  if (result == VK_SUCCESS) return;
  const std::string message = std::string(call) + " failed: " + resultName(result) + " (" + std::to_string(result) + ")";
  if (result == VK_ERROR_DEVICE_LOST) throw DeviceLost(message);
  throw Error(message);
}
}  // namespace hp::vk
