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
  ValidationLog* capturing = nullptr;  // the creating context's log while vkCreateInstance runs, else null
};

Cache& cache() {
  static Cache* c = new Cache();  // never destroyed, like the instances it holds
  return *c;
}

// The messenger chained into vkCreateInstance: its user data is the cache, which outlives every instance,
// so a layer that kept calling it later would find no log (dropped) instead of a freed one.
VKAPI_ATTR VkBool32 VKAPI_CALL creationCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                VkDebugUtilsMessageTypeFlagsEXT types,
                                                const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
  ValidationLog* log = static_cast<Cache*>(user)->capturing;
  return log ? ValidationLog::callback(severity, types, data, log) : VK_FALSE;
}

std::string key(const InstanceRequest& r) {
  std::vector<std::string> extensions = r.extensions;
  std::sort(extensions.begin(), extensions.end());
  std::string k = r.validation ? "validation|" : "|";
  for (const auto& e : extensions) k += e + ",";
  return k;
}

VkInstance create(const InstanceRequest& request, Cache& cache) {
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
  VkDebugUtilsMessengerCreateInfoEXT messenger = ValidationLog::messengerInfo(nullptr);
  messenger.pfnUserCallback = &creationCallback;
  messenger.pUserData = &cache;
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
  struct Capture {  // the creating context's log takes vkCreateInstance's messages, and only those
    Cache& c;
    ~Capture() { c.capturing = nullptr; }
  } capture{c};
  c.capturing = &log;
  VkInstance instance = create(request, c);
  c.instances.emplace(k, instance);
  return instance;
}

std::size_t sharedInstanceCount() {
  Cache& c = cache();
  std::lock_guard<std::mutex> lock(c.mutex);
  return c.instances.size();
}
}  // namespace hp::vk
