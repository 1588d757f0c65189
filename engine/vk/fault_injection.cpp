#include "engine/vk/fault_injection.h"

#include <atomic>
#include <mutex>

namespace hp::vk {
namespace {
struct ArmedFault {
  std::string call;
  VkResult result = VK_SUCCESS;
  int skip = 0;
};
std::atomic<bool> armed{false};  // the fast path of every check() while nothing is armed
std::mutex faultMutex;
ArmedFault fault;
}  // namespace

void armFault(const std::string& call, VkResult result, int skip) {
  std::lock_guard<std::mutex> lock(faultMutex);
  fault = {call, result, skip};
  armed.store(true);
}

void disarmFault() {
  std::lock_guard<std::mutex> lock(faultMutex);
  armed.store(false);
}

bool faultArmed() { return armed.load(); }

VkResult injectFault(const char* call, VkResult actual) {
  if (!armed.load() || actual != VK_SUCCESS) return actual;
  std::lock_guard<std::mutex> lock(faultMutex);
  if (!armed.load() || std::string(call).rfind(fault.call, 0) != 0) return actual;
  if (fault.skip-- > 0) return actual;
  armed.store(false);
  return fault.result;
}
}  // namespace hp::vk
