#pragma once
// Contract: the Vulkan instance/device hairpipe works with, either created headless by hairpipe
// (createHeadless) or handed over by the embedding application (adopt). It owns only what it created: a
// headless context owns its device and debug messenger; its VkInstance is the process's shared one for
// its options (instance_cache.h), kept until exit, because a driver may refuse new instances after many.
// Device functions are called through the context's own table (volk's VolkDeviceTable, fn()), so several
// contexts may drive several devices in one process. Instance-level functions live in hairpipe's private
// copy of volk (third_party/volk: its globals are renamed hpvk_*), loaded from the vkGetInstanceProcAddr
// the application hands over (adopt) or from libvulkan (createHeadless); an application's own loader
// symbols or volk globals are never defined or touched by hairpipe. createHeadless also loads the
// private device-level globals for its device: a headless context is its program's only device (the
// tool, the tests).
// Required: Vulkan 1.3 with dynamicRendering and synchronization2 enabled, and a graphics+compute queue.
// With validation on, VK_LAYER_KHRONOS_validation runs with synchronization validation and every
// message lands in validationLog(); a missing layer is an error, never a silent downgrade.
#include "hairpipe_volk.h"

#include <cstdint>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

#include "engine/vk/descriptor_pools.h"
#include "engine/vk/device_selection.h"
#include "engine/vk/memory_pool.h"
#include "hairpipe/context.h"
#include "engine/vk/validation_log.h"

namespace hp::vk {
class OneShotBatch;

struct ContextOptions {
  bool validation = false;
  std::string device;  // --device NAME-SUBSTRING|INDEX; empty: HAIRPIPE_DEVICE, else the best device
  std::string appName = "hairpipe";  // names the shared instance only when this context creates it
  // Extra extensions (a windowed tool: the surface ones and VK_KHR_swapchain); a missing one is an
  // hp::Error naming it. hairpipe itself needs none.
  std::vector<std::string> instanceExtensions;
  std::vector<std::string> deviceExtensions;
};

// Handles owned by an embedding application (defined once, in the public API: hairpipe::DeviceHandles).
// hairpipe never destroys them and never waits idle on the device. The device must have been created with
// apiVersion 1.3 and dynamicRendering + synchronization2 enabled (features adopt() cannot query: it checks
// the version, the queue family and the functions). hairpipe's one-shot work outside the frame loop
// (construction uploads, setMaterial, reset) submits to `queue` and waits on its own fence: the
// application must not use that queue from another thread then.
using ExternalDevice = hairpipe::DeviceHandles;

class Context {
 public:
  static std::unique_ptr<Context> createHeadless(const ContextOptions& options);
  static std::unique_ptr<Context> adopt(const ExternalDevice& external);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  VkDevice device() const { return device_; }
  // The device's functions: ctx.fn().vkCmdDispatch(cmd, ...). Valid as long as the context.
  const VolkDeviceTable& fn() const { return fn_; }
  VkQueue queue() const { return queue_; }
  std::uint32_t queueFamily() const { return queueFamily_; }
  VkCommandPool transientPool() const { return transientPool_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  const VkPhysicalDeviceMemoryProperties& memoryProperties() const { return memory_; }
  bool timestampsSupported() const { return timestampsSupported_; }
  bool validationEnabled() const { return validation_; }
  // The device has the independentBlend feature enabled (headless: where it has it; adopted: as the
  // application says), which AttachmentFormats::otherColors needs.
  bool independentBlend() const { return independentBlend_; }
  ValidationLog& validationLog() { return *log_; }
  // Shared so a test can still read messages reported while the device is destroyed.
  std::shared_ptr<ValidationLog> sharedValidationLog() const { return log_; }
  const DeviceChoice& selection() const { return choice_; }

  // A memory type index with all `required` flags, preferring one that also has `preferred`.
  std::uint32_t findMemoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required,
                               VkMemoryPropertyFlags preferred = 0) const;
  // Debug name for any object (no-op when VK_EXT_debug_utils is off).
  void setName(VkObjectType type, std::uint64_t handle, const std::string& name) const;
  // Only on a device hairpipe created; throws hp::Error on an adopted one.
  void waitIdle() const;
  // Size of the largest device-local heap: the budget that size checks of big allocations use.
  VkDeviceSize deviceLocalHeapBytes() const;
  // Bytes of device memory hairpipe's buffers and images hold now (what `hairpipe bench instances` reports).
  std::uint64_t allocatedBytes() const { return allocated_->load(); }
  // Shared with every buffer and image, which add their allocation and take it back when freed.
  const std::shared_ptr<std::atomic<std::int64_t>>& allocationTally() const { return allocated_; }
  // The batch that one-shot work records into now (submit.h), or null: submit each at once.
  OneShotBatch* openBatch() const { return batch_; }
  // The most device memory hairpipe may hold at once (0: no cap but the heaps), for an application that
  // budgets its middleware. An allocation past it fails as the driver's out-of-memory does.
  void setDeviceMemoryBudget(VkDeviceSize bytes) { budget_.store(bytes); }
  VkDeviceSize deviceMemoryBudget() const { return budget_.load(); }
  // Called before every allocation: throws hp::Error naming VK_ERROR_OUT_OF_DEVICE_MEMORY, `what` and the
  // budget when `bytes` more would exceed it.
  void checkDeviceMemoryBudget(VkDeviceSize bytes, const std::string& what) const;
  // Where buffers and images get their memory (memory_pool.h).
  MemoryPool& memoryPool() const { return *memoryPool_; }
  // Where descriptor sets come from (descriptor_pools.h).
  DescriptorPools& descriptorPools() const { return *descriptorPools_; }

 private:
  friend class OneShotBatch;
  void setOpenBatch(OneShotBatch* batch) const { batch_ = batch; }
  Context() = default;
  void createInstance(const ContextOptions& options);
  void createDevice(const ContextOptions& options);
  void finishSetup();
  void checkAdopted() const;

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VolkDeviceTable fn_{};
  VkQueue queue_ = VK_NULL_HANDLE;
  std::uint32_t queueFamily_ = 0;
  VkCommandPool transientPool_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  bool ownsDevice_ = false;
  bool debugUtils_ = false;
  bool independentBlend_ = false;
  bool validation_ = false;
  bool timestampsSupported_ = false;
  std::shared_ptr<ValidationLog> log_ = std::make_shared<ValidationLog>();
  std::shared_ptr<std::atomic<std::int64_t>> allocated_ = std::make_shared<std::atomic<std::int64_t>>(0);
  std::atomic<VkDeviceSize> budget_{0};
  DeviceChoice choice_;
  mutable OneShotBatch* batch_ = nullptr;
  std::unique_ptr<MemoryPool> memoryPool_;
  std::unique_ptr<DescriptorPools> descriptorPools_;
};

// Loads the Vulkan loader through volk once per process; throws hp::Error when it is missing.
void initializeLoader();
// Loads hairpipe's instance-level functions for `instance` through the application's loader entry point.
void loadInstanceFunctions(PFN_vkGetInstanceProcAddr getInstanceProcAddr, VkInstance instance);
bool instanceLayerAvailable(const char* name);
}  // namespace hp::vk
