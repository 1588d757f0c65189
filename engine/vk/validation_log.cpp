#include "engine/vk/validation_log.h"

#include <iostream>

namespace hp::vk {
namespace {
bool isProblem(VkDebugUtilsMessageSeverityFlagBitsEXT severity) {
  return severity >= VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT;
}
}  // namespace

void ValidationLog::record(ValidationMessage message) {
  std::lock_guard lock(mutex_);
  if (echo_ && isProblem(message.severity)) std::cerr << "vulkan validation: " << message.text << "\n";
  messages_.push_back(std::move(message));
}

std::vector<ValidationMessage> ValidationLog::messages() const {
  std::lock_guard lock(mutex_);
  return messages_;
}

std::size_t ValidationLog::problemCount() const {
  std::lock_guard lock(mutex_);
  std::size_t n = 0;
  for (const auto& m : messages_) n += isProblem(m.severity) ? 1 : 0;
  return n;
}

std::string ValidationLog::describeProblems() const {
  std::lock_guard lock(mutex_);
  std::string out;
  for (const auto& m : messages_)
    if (isProblem(m.severity)) out += "[" + m.idName + "] " + m.text + "\n";
  return out;
}

void ValidationLog::clear() {
  std::lock_guard lock(mutex_);
  messages_.clear();
}

VkDebugUtilsMessengerCreateInfoEXT ValidationLog::messengerInfo(ValidationLog* log) {
  VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                     VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  info.pfnUserCallback = &ValidationLog::callback;
  info.pUserData = log;
  return info;
}

VKAPI_ATTR VkBool32 VKAPI_CALL ValidationLog::callback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                       VkDebugUtilsMessageTypeFlagsEXT,
                                                       const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                       void* userData) {
  auto* log = static_cast<ValidationLog*>(userData);
  log->record({severity, data->pMessageIdName ? data->pMessageIdName : "",
               data->pMessage ? data->pMessage : ""});
  return VK_FALSE;  // never abort the call that triggered the message
}
}  // namespace hp::vk
