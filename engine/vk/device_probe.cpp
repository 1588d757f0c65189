#include "engine/vk/device_probe.h"

#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp::vk {
DeviceKind deviceKind(VkPhysicalDeviceType type) {
  switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return DeviceKind::Discrete;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return DeviceKind::Integrated;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return DeviceKind::Virtual;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return DeviceKind::Cpu;
    default: return DeviceKind::Other;
  }
}

namespace {
void probeQueues(DeviceReport& report) {
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(report.handle, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(report.handle, &count, families.data());
  const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  for (std::uint32_t i = 0; i < count; ++i) {
    if ((families[i].queueFlags & needed) == needed) {
      report.queueFamily = static_cast<std::int32_t>(i);
      report.timestamps = families[i].timestampValidBits > 0;
      return;
    }
  }
  report.candidate.missing.push_back("a graphics+compute queue");
}

void probeFeatures(DeviceReport& report) {
  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v13};
  vkGetPhysicalDeviceFeatures2(report.handle, &features);
  if (!v13.dynamicRendering) report.candidate.missing.push_back("feature dynamicRendering");
  if (!v13.synchronization2) report.candidate.missing.push_back("feature synchronization2");
}
}  // namespace

std::vector<DeviceReport> probeDevices(VkInstance instance) {
  std::uint32_t count = 0;
  HP_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
  std::vector<VkPhysicalDevice> handles(count);
  HP_VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, handles.data()));
  std::vector<DeviceReport> reports;
  for (std::uint32_t i = 0; i < count; ++i) reports.push_back(probeDevice(handles[i], i));
  return reports;
}

DeviceRequirements requirements() { return {}; }

bool independentBlendSupported(VkPhysicalDevice device) {
  VkPhysicalDeviceFeatures features{};
  vkGetPhysicalDeviceFeatures(device, &features);
  return features.independentBlend == VK_TRUE;
}

bool computeSubgroupOperations(VkPhysicalDevice device) {
  VkPhysicalDeviceSubgroupProperties subgroups{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES};
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &subgroups};
  vkGetPhysicalDeviceProperties2(device, &props);
  const VkSubgroupFeatureFlags needed =
      VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_BALLOT_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT;
  return (subgroups.supportedStages & VK_SHADER_STAGE_COMPUTE_BIT) != 0 &&
         (subgroups.supportedOperations & needed) == needed;
}

std::vector<std::string> unfitReasons(VkPhysicalDevice device) { return probeDevice(device, 0).candidate.missing; }

DeviceReport probeDevice(VkPhysicalDevice device, std::uint32_t i) {
  DeviceReport r;
  r.handle = device;
  r.driver.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
  VkPhysicalDeviceProperties2 props{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &r.driver};
  vkGetPhysicalDeviceProperties2(r.handle, &props);
  r.properties = props.properties;
  vkGetPhysicalDeviceMemoryProperties(r.handle, &r.memory);
  r.candidate.index = i;
  r.candidate.name = r.properties.deviceName;
  r.candidate.kind = deviceKind(r.properties.deviceType);
  r.candidate.apiVersion = r.properties.apiVersion;
  if (r.properties.apiVersion < VK_API_VERSION_1_3) {
    r.candidate.missing.push_back("Vulkan 1.3");
  } else {
    probeFeatures(r);
    if (!computeSubgroupOperations(device)) r.candidate.missing.push_back(requirements().subgroups);
  }
  probeQueues(r);
  return r;
}
InstanceProbe::InstanceProbe() {
  initializeLoader();
  loaderVersion_ = volkGetInstanceVersion();
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "hairpipe info";
  app.apiVersion = VK_API_VERSION_1_3;
  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pApplicationInfo = &app;
  HP_VK_CHECK(vkCreateInstance(&info, nullptr, &instance_));
  volkLoadInstanceOnly(instance_);
  devices_ = probeDevices(instance_);
}

InstanceProbe::~InstanceProbe() {
  if (instance_) vkDestroyInstance(instance_, nullptr);
}
}  // namespace hp::vk
