#include "engine/vk/instance_cache.h"

#include <algorithm>
#include <map>
#include <mutex>

#include "engine/vk/check.h"

namespace hp::vk {
namespace {
struct Cache {
  std::mutex mutex;
  std::map<std::string, VkInstance> instances;  // by key(request)
  ValidationLog creationLog;  // outlives every instance: the layer may keep the creation messenger's pointer
};

Cache& cache() {
  static Cache* c = new Cache();  // never destroyed, like the instances it holds
  return *c;
}

std::string key(const InstanceRequest& r) {
  std::vector<std::string> extensions = r.extensions;
  std::sort(extensions.begin(), extensions.end());
  std::string k = r.validation ? "validation|" : "|";
  for (const auto& e : extensions) k += e + ",";
  return k;
}

VkInstance create(const InstanceRequest& request, ValidationLog& creationLog) {
  std::vector<const char*> layers, extensions;
  if (request.validation) layers.push_back(kValidationLayer);
  for (const auto& e : request.extensions) extensions.push_back(e.c_str());
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = request.appName.c_str();
  app.pEngineName = "hairpipe";
  app.apiVersion = VK_API_VERSION_1_3;
  // Synchronization validation is opt-in in the layer.
  VkValidationFeatureEnableEXT enables[] = {VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = enables;
  VkDebugUtilsMessengerCreateInfoEXT messenger = ValidationLog::messengerInfo(&creationLog);
  messenger.pNext = &features;

  VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  info.pNext = request.validation ? &messenger : nullptr;  // also vkCreateInstance's own messages
  info.pApplicationInfo = &app;
  info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
  info.ppEnabledLayerNames = layers.data();
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  VkInstance instance = VK_NULL_HANDLE;
  HP_VK_CHECK(vkCreateInstance(&info, nullptr, &instance));
  return instance;
}
}  // namespace

VkInstance sharedInstance(const InstanceRequest& request, ValidationLog& log) {
  Cache& c = cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  const std::string k = key(request);
  if (auto it = c.instances.find(k); it != c.instances.end()) return it->second;
  c.creationLog.clear();
  VkInstance instance = create(request, c.creationLog);
  for (const ValidationMessage& m : c.creationLog.messages()) log.record(m);
  c.creationLog.clear();
  c.instances.emplace(k, instance);
  return instance;
}

std::size_t sharedInstanceCount() {
  Cache& c = cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  return c.instances.size();
}
}  // namespace hp::vk
