#pragma once
// Contract: a bare instance for looking at devices (no device created, no validation), used by
// `hairpipe info`. Destroys its instance on scope exit.
#include "hairpipe_volk.h"

#include <cstdint>

#include <vector>

#include "engine/vk/device_probe.h"

namespace hp::vk {
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
