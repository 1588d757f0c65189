#include "engine/vk/instance_probe.h"

#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp::vk {
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
