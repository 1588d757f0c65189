#pragma once
// Contract: reads what each physical device offers (for selection and for `hairpipe info`) and decides
// what hairpipe needs that it lacks. Needs a live instance; the decision logic is in device_selection.
// InstanceProbe is a bare instance for looking at devices (no device created, no validation), used by
// `hairpipe info`; it destroys its instance on scope exit.
#include "hairpipe_volk.h"

#include <cstdint>

#include <string>
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
DeviceReport probeDevice(VkPhysicalDevice device, std::uint32_t index);

// What an application must create its device with to hand it to hairpipe (Context::adopt).
struct DeviceRequirements {
  std::uint32_t apiVersion = VK_API_VERSION_1_3;
  std::vector<std::string> features{"VkPhysicalDeviceVulkan13Features::dynamicRendering",
                                    "VkPhysicalDeviceVulkan13Features::synchronization2"};
  std::vector<std::string> extensions;  // none required; VK_EXT_debug_utils is used for names when enabled
  // Properties, not features (nothing to enable): the passes reduce and allot through subgroups.
  std::string subgroups = "subgroup operations basic, ballot and arithmetic in compute shaders";
  std::string queue = "one queue family with VK_QUEUE_GRAPHICS_BIT and VK_QUEUE_COMPUTE_BIT";
};
DeviceRequirements requirements();
// Why `device` cannot run hairpipe (e.g. "Vulkan 1.3", "feature synchronization2"); empty when it can.
std::vector<std::string> unfitReasons(VkPhysicalDevice device);
DeviceKind deviceKind(VkPhysicalDeviceType type);
// Whether the device's compute shaders have the subgroup operations of DeviceRequirements::subgroups.
bool computeSubgroupOperations(VkPhysicalDevice device);
// Whether the device has the independentBlend feature (AttachmentFormats::otherColors needs it enabled).
bool independentBlendSupported(VkPhysicalDevice device);

class InstanceProbe {
 public:
  InstanceProbe();
  ~InstanceProbe();
  InstanceProbe(const InstanceProbe&) = delete;
  InstanceProbe& operator=(const InstanceProbe&) = delete;
  const std::vector<DeviceReport>& devices() const { return devices_; }
  std::uint32_t loaderVersion() const { return loaderVersion_; }

 private:
  VkInstance instance_ = VK_NULL_HANDLE;
  std::vector<DeviceReport> devices_;
  std::uint32_t loaderVersion_ = 0;
};
}  // namespace hp::vk
