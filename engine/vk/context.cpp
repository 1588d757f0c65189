#include "engine/vk/context.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "engine/core/error.h"
#include "engine/vk/check.h"
#include "engine/vk/device_probe.h"
#include "engine/vk/instance_cache.h"

namespace hp::vk {
namespace {
bool instanceExtensionAvailable(const char* name) {
  std::uint32_t count = 0;
  HP_VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, nullptr));
  std::vector<VkExtensionProperties> exts(count);
  HP_VK_CHECK(vkEnumerateInstanceExtensionProperties(nullptr, &count, exts.data()));
  for (const auto& e : exts)
    if (std::strcmp(e.extensionName, name) == 0) return true;
  return false;
}

bool deviceExtensionAvailable(VkPhysicalDevice device, const std::string& name) {
  std::uint32_t count = 0;
  HP_VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
  std::vector<VkExtensionProperties> exts(count);
  HP_VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, exts.data()));
  for (const auto& e : exts)
    if (name == e.extensionName) return true;
  return false;
}

std::string requestedDevice(const ContextOptions& options) {
  if (!options.device.empty()) return options.device;
  const char* env = std::getenv("HAIRPIPE_DEVICE");
  return env ? env : "";
}
}  // namespace

void initializeLoader() {
  static bool loaded = false;
  if (loaded) return;
  if (volkInitialize() != VK_SUCCESS)
    throw Error("the Vulkan loader (libvulkan.so.1) was not found; install libvulkan1 and a driver such as mesa-vulkan-drivers");
  loaded = true;
}

// hairpipe's private volk copy (hpvk_* symbols) holds the instance-level functions; device functions go
// into each context's table. The application's own loader or volk globals are other symbols, never touched.
void loadInstanceFunctions(PFN_vkGetInstanceProcAddr getInstanceProcAddr, VkInstance instance) {
  if (volkGetLoadedInstance() == instance) return;
  volkInitializeCustom(getInstanceProcAddr);
  volkLoadInstanceOnly(instance);
}

bool instanceLayerAvailable(const char* name) {
  initializeLoader();
  std::uint32_t count = 0;
  HP_VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
  std::vector<VkLayerProperties> layers(count);
  HP_VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
  for (const auto& l : layers)
    if (std::strcmp(l.layerName, name) == 0) return true;
  return false;
}

std::unique_ptr<Context> Context::createHeadless(const ContextOptions& options) {
  initializeLoader();
  std::unique_ptr<Context> ctx(new Context());
  ctx->ownsDevice_ = true;
  ctx->createInstance(options);
  ctx->createDevice(options);
  ctx->finishSetup();
  return ctx;
}

std::unique_ptr<Context> Context::adopt(const ExternalDevice& external) {
  if (!external.getInstanceProcAddr || !external.instance || !external.physicalDevice || !external.device ||
      !external.queue)
    throw Error("Context::adopt: every handle of ExternalDevice (getInstanceProcAddr, instance, physicalDevice, "
                "device, queue) must be set");
  loadInstanceFunctions(external.getInstanceProcAddr, external.instance);
  std::unique_ptr<Context> ctx(new Context());
  ctx->instance_ = external.instance;
  ctx->physical_ = external.physicalDevice;
  ctx->device_ = external.device;
  volkLoadDeviceTable(&ctx->fn_, external.device);
  ctx->queue_ = external.queue;
  ctx->queueFamily_ = external.queueFamily;
  ctx->debugUtils_ = external.debugUtilsEnabled;
  ctx->independentBlend_ = external.independentBlendEnabled;
  ctx->checkAdopted();
  ctx->finishSetup();
  return ctx;
}

// An adopted device is the application's: it cannot be probed for enabled features, but what can be
// checked is, so a wrong device fails here with a message instead of crashing in a later command.
void Context::checkAdopted() const {
  VkPhysicalDeviceProperties props;
  vkGetPhysicalDeviceProperties(physical_, &props);
  if (props.apiVersion < VK_API_VERSION_1_3)
    throw Error(std::string("Context::adopt: ") + props.deviceName + " is not a Vulkan 1.3 device");
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, families.data());
  const VkQueueFlags needed = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
  if (queueFamily_ >= count || (families[queueFamily_].queueFlags & needed) != needed)
    throw Error("Context::adopt: queue family " + std::to_string(queueFamily_) + " does not support graphics and compute");
  if (independentBlend_ && !independentBlendSupported(physical_))
    throw Error(std::string("Context::adopt: DeviceHandles::independentBlendEnabled is set, but ") + props.deviceName +
                " has no independentBlend feature");
  if (!computeSubgroupOperations(physical_))
    throw Error(std::string("Context::adopt: ") + props.deviceName + " lacks " + requirements().subgroups);
  if (!fn_.vkCmdPipelineBarrier2 || !fn_.vkCmdBeginRendering || !fn_.vkQueueSubmit2)
    throw Error("Context::adopt: Vulkan 1.3 device functions did not load (was the device created with apiVersion 1.3?)");
}

// The instance is the process's shared one for these options (instance_cache.h); only the messenger is
// this context's.
void Context::createInstance(const ContextOptions& options) {
  InstanceRequest request;
  request.appName = options.appName;
  if (instanceExtensionAvailable(VK_EXT_DEBUG_UTILS_EXTENSION_NAME)) {
    request.extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    debugUtils_ = true;
  }
  validation_ = request.validation = options.validation;
  if (validation_) {
    if (!instanceLayerAvailable(kValidationLayer))
      throw Error("validation was requested but VK_LAYER_KHRONOS_validation is not installed (vulkan-validationlayers)");
    if (!debugUtils_) throw Error("validation was requested but VK_EXT_debug_utils is not available");
  }
  for (const auto& e : options.instanceExtensions) {
    if (!instanceExtensionAvailable(e.c_str())) throw Error("the Vulkan instance extension " + e + " is not available");
    request.extensions.push_back(e);
  }
  instance_ = sharedInstance(request, *log_);
  volkLoadInstanceOnly(instance_);
  if (validation_) {
    VkDebugUtilsMessengerCreateInfoEXT m = ValidationLog::messengerInfo(log_.get());
    HP_VK_CHECK(vkCreateDebugUtilsMessengerEXT(instance_, &m, nullptr, &messenger_));
  }
}

void Context::createDevice(const ContextOptions& options) {
  std::vector<DeviceReport> reports = probeDevices(instance_);
  std::vector<DeviceCandidate> candidates;
  for (const auto& r : reports) candidates.push_back(r.candidate);
  choice_ = chooseDevice(candidates, requestedDevice(options));
  if (!choice_.chosen) throw Error(choice_.error);
  const DeviceReport& chosen = reports[*choice_.chosen];
  physical_ = chosen.handle;
  queueFamily_ = static_cast<std::uint32_t>(chosen.queueFamily);

  float priority = 1.0f;
  VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  queueInfo.queueFamilyIndex = queueFamily_;
  queueInfo.queueCount = 1;
  queueInfo.pQueuePriorities = &priority;
  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  v13.dynamicRendering = VK_TRUE;
  v13.synchronization2 = VK_TRUE;
  VkPhysicalDeviceFeatures2 features{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &v13};
  independentBlend_ = independentBlendSupported(physical_);  // for AttachmentFormats::otherColors
  features.features.independentBlend = independentBlend_ ? VK_TRUE : VK_FALSE;
  std::vector<const char*> extensions;
  for (const auto& e : options.deviceExtensions) {
    if (!deviceExtensionAvailable(physical_, e))
      throw Error(std::string(chosen.candidate.name) + " does not support the device extension " + e);
    extensions.push_back(e.c_str());
  }
  VkDeviceCreateInfo info{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features};
  info.queueCreateInfoCount = 1;
  info.pQueueCreateInfos = &queueInfo;
  info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
  info.ppEnabledExtensionNames = extensions.data();
  HP_VK_CHECK(vkCreateDevice(physical_, &info, nullptr, &device_));
  volkLoadDeviceTable(&fn_, device_);
  volkLoadDevice(device_);  // the headless program's own direct calls (see the contract)
  fn_.vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);
}

void Context::finishSetup() {
  vkGetPhysicalDeviceProperties(physical_, &properties_);
  vkGetPhysicalDeviceMemoryProperties(physical_, &memory_);
  std::uint32_t count = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, nullptr);
  std::vector<VkQueueFamilyProperties> families(count);
  vkGetPhysicalDeviceQueueFamilyProperties(physical_, &count, families.data());
  if (queueFamily_ >= count) throw Error("queue family index " + std::to_string(queueFamily_) + " is out of range");
  timestampsSupported_ = families[queueFamily_].timestampValidBits > 0 && properties_.limits.timestampPeriod > 0.0f;

  VkCommandPoolCreateInfo pool{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pool.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pool.queueFamilyIndex = queueFamily_;
  HP_VK_CHECK(fn_.vkCreateCommandPool(device_, &pool, nullptr, &transientPool_));
  setName(VK_OBJECT_TYPE_COMMAND_POOL, reinterpret_cast<std::uint64_t>(transientPool_), "hairpipe transient pool");
  memoryPool_ = std::make_unique<MemoryPool>(*this);
  descriptorPools_ = std::make_unique<DescriptorPools>(*this);
}

Context::~Context() {
  // An adopted device belongs to the application: never wait idle on it, the app has already
  // ensured hairpipe's work is finished before destroying hairpipe (see the embedding contract).
  if (ownsDevice_ && device_) fn_.vkDeviceWaitIdle(device_);
  descriptorPools_.reset();  // destroys what is left (nothing, when every set went first)
  memoryPool_.reset();       // frees what is left (nothing, when every buffer and image went first)
  if (transientPool_) fn_.vkDestroyCommandPool(device_, transientPool_, nullptr);
  if (!ownsDevice_) return;
  if (device_) fn_.vkDestroyDevice(device_, nullptr);
  if (messenger_) vkDestroyDebugUtilsMessengerEXT(instance_, messenger_, nullptr);
  // The instance stays: the process's shared one (instance_cache.h).
}

std::uint32_t Context::findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required,
                                      VkMemoryPropertyFlags preferred) const {
  std::int32_t fallback = -1;
  for (std::uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if (!(typeBits & (1u << i))) continue;
    VkMemoryPropertyFlags flags = memory_.memoryTypes[i].propertyFlags;
    if ((flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (fallback < 0) fallback = static_cast<std::int32_t>(i);
  }
  if (fallback < 0) throw Error("no Vulkan memory type with the required properties (flags " + std::to_string(required) + ")");
  return static_cast<std::uint32_t>(fallback);
}

void Context::setName(VkObjectType type, std::uint64_t handle, const std::string& name) const {
  if (!debugUtils_ || !vkSetDebugUtilsObjectNameEXT || handle == 0) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name.c_str();
  HP_VK_CHECK(vkSetDebugUtilsObjectNameEXT(device_, &info));
}

void Context::waitIdle() const {
  if (!ownsDevice_) throw Error("Context::waitIdle: the device belongs to the application; hairpipe never waits idle on it");
  HP_VK_CHECK(fn_.vkDeviceWaitIdle(device_));
}

void Context::checkDeviceMemoryBudget(VkDeviceSize bytes, const std::string& what) const {
  const VkDeviceSize budget = deviceMemoryBudget();
  const auto held = static_cast<VkDeviceSize>(std::max<std::int64_t>(0, allocated_->load()));
  if (budget == 0 || held + bytes <= budget) return;
  throw Error("vkAllocateMemory refused: VK_ERROR_OUT_OF_DEVICE_MEMORY (" + what + ": " + std::to_string(bytes) +
              " bytes more than the " + std::to_string(budget - std::min(budget, held)) +
              " left of hairpipe's device memory budget of " + std::to_string(budget) + " bytes)");
}

VkDeviceSize Context::deviceLocalHeapBytes() const {
  VkDeviceSize best = 0;
  for (std::uint32_t i = 0; i < memory_.memoryHeapCount; ++i)
    if (memory_.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) best = std::max(best, memory_.memoryHeaps[i].size);
  return best;
}
}  // namespace hp::vk
