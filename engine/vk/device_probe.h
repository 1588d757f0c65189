#pragma once
// Contract: reads what each physical device offers (for selection and for `hairpipe info`) and decides
// what hairpipe needs that it lacks. Needs a live instance; the decision logic is in device_selection.
#include <volk.h>

#include <cstdint>

#include <vector>

#include "engine/vk/device_selection.h"

namespace hp::vk {
struct DeviceReport {
  VkPhysicalDevice handle = VK_NULL_HANDLE;
  DeviceCandidate candidate;
  VkPhysicalDeviceProperties properties{};
  VkPhysicalDeviceDriverProperties driver{};
  VkPhysicalDeviceMemoryProperties memory{};
  std::int32_t queueFamily = -1;  // first graphics+compute family, -1 if none
  bool timestamps = false;        // timestamps on that queue family
};

std::vector<DeviceReport> probeDevices(VkInstance instance);
DeviceKind deviceKind(VkPhysicalDeviceType type);
}  // namespace hp::vk
