#pragma once
// Contract: collects every message the validation layer (via VK_EXT_debug_utils) reports, thread-safely.
// Tests fail on any warning or error recorded here; the CLI prints them to stderr.
#include "hairpipe_volk.h"

#include <cstdint>

#include <mutex>
#include <string>
#include <vector>

namespace hp::vk {
struct ValidationMessage {
  VkDebugUtilsMessageSeverityFlagBitsEXT severity;
  std::string idName;
  std::string text;
};

class ValidationLog {
 public:
  void record(ValidationMessage message);
  std::vector<ValidationMessage> messages() const;
  // Warnings and errors only (info/verbose are ignored by the fixtures).
  std::size_t problemCount() const;
  std::string describeProblems() const;
  void clear();
  void setEcho(bool echo) { echo_ = echo; }

  // A messenger for warnings and errors of every type into `log` (callback below).
  static VkDebugUtilsMessengerCreateInfoEXT messengerInfo(ValidationLog* log);
  // The debug-utils callback; pUserData is a ValidationLog*.
  static VKAPI_ATTR VkBool32 VKAPI_CALL callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT types,
                                                 const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                 void* userData);

 private:
  mutable std::mutex mutex_;
  std::vector<ValidationMessage> messages_;
  bool echo_ = false;
};
}  // namespace hp::vk
