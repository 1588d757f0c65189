#pragma once
// Contract: the VkInstances of headless contexts, one per distinct set of layers and extensions, created
// on first use and kept for the process's life; every headless Context with the same set shares it.
// Why: NVIDIA's driver (580.159, H100) refuses vkCreateInstance with VK_ERROR_INCOMPATIBLE_DRIVER after
// about 30 instances were created and destroyed in one process, so an engine that remakes hairpipe's device
// (after a device loss, a settings change) or a test run would stop working; devices still come and go.
// The instances are never destroyed (the driver and loader go with the process), so the layer's checks at
// vkDestroyInstance (children left alive) no longer run; devices are still checked at vkDestroyDevice.
// The cache is thread-safe (creating headless contexts concurrently is not: volk's private globals).
// With validation, each Context adds its own debug messenger; messages about one context's device then
// reach every validating context alive at the time, and those of vkCreateInstance itself reach the
// context that created the instance (`log`).
#include "hairpipe_volk.h"

#include <string>
#include <vector>

#include "engine/vk/validation_log.h"

namespace hp::vk {
inline constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

struct InstanceRequest {
  bool validation = false;              // kValidationLayer with synchronization validation
  std::vector<std::string> extensions;  // order does not matter
  std::string appName;                  // the first request's names the instance
};

// The instance for `request` (keyed by `validation` and the set of `extensions`), created now (its
// creation's validation messages go to `log`) or shared.
// Throws hp::Error naming the call when the driver refuses it.
VkInstance sharedInstance(const InstanceRequest& request, ValidationLog& log);
// Instances created so far in this process (tests: repeated contexts must not add any).
std::size_t sharedInstanceCount();
}  // namespace hp::vk
