#pragma once
// Contract: the Vulkan device hairpipe works on. Either the application hands over its own (adopt: the
// usual case for an engine) or hairpipe creates a headless one (createHeadless: tools, tests, offline
// rendering). hairpipe loads every Vulkan function it calls into its own tables from the
// vkGetInstanceProcAddr it is given (or from libvulkan.so.1 for a headless device): it defines no global
// vk* symbol and never touches an application's loader or volk pointers.
//
// The device must be Vulkan 1.3 with dynamicRendering and synchronization2 enabled, the subgroup operations
// basic, ballot and arithmetic in compute shaders (a property: nothing to enable) and a queue family with
// graphics and compute; requirements() lists it, unfitReasons() says why a physical device cannot serve.
// hairpipe never destroys what it adopted and never waits idle on an adopted device. Its one-shot work
// outside the frame loop (construction uploads, material changes) submits to the given queue and waits on
// its own fence: the application must not use that queue from another thread during those calls.
// A Context must outlive every Renderer made on it. A Context and what is made on it are used by one thread
// at a time (hairpipe/renderer.h, "Threads").
// A headless Context owns its device; its VkInstance is shared by every headless Context of the process
// with the same validation setting and lives until the process ends (a driver may refuse new instances after many
// were created and destroyed: NVIDIA 580 did from the 30th). With validation, each Context's log then
// also receives the messages about the other validating headless Contexts alive at the same time.
#include <vulkan/vulkan_core.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "hairpipe/result.h"

namespace hp::vk {
class Context;  // the implementation (private)
}

namespace hairpipe {
struct Access;

struct DeviceHandles {  // an application's device, which stays the application's
  PFN_vkGetInstanceProcAddr getInstanceProcAddr = nullptr;
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physicalDevice = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  std::uint32_t queueFamily = 0;
  VkQueue queue = VK_NULL_HANDLE;
  bool debugUtilsEnabled = false;  // the instance has VK_EXT_debug_utils: hairpipe names its objects
  // The device was created with VkPhysicalDeviceFeatures::independentBlend: needed for
  // AttachmentFormats::otherColors (hairpipe's pipelines write the first colour and, where
  // RendererSettings::velocityOutput names one, the velocity's two channels, each attachment its own mask).
  bool independentBlendEnabled = false;
};

struct HeadlessOptions {
  bool validation = false;  // Khronos validation with synchronization validation; messages are counted
  std::string device;       // a name substring or index; empty: HAIRPIPE_DEVICE, else the best device
};

class Context {
 public:
  // A moved-from Context answers with null handles and failures.
  static Result<Context> adopt(const DeviceHandles& device) noexcept;
  static Result<Context> createHeadless(const HeadlessOptions& options) noexcept;
  Context(Context&&) noexcept;
  Context& operator=(Context&&) noexcept;
  ~Context();

  VkInstance instance() const noexcept;
  VkPhysicalDevice physicalDevice() const noexcept;
  VkDevice device() const noexcept;
  VkQueue queue() const noexcept;
  std::uint32_t queueFamily() const noexcept;
  const char* deviceName() const noexcept;
  // Headless with validation: the validation messages reported so far (warnings and errors).
  Result<std::vector<std::string>> validationMessages() const noexcept;
  // A headless device's vkDeviceWaitIdle; on an adopted device a failure (the device is the application's).
  Status waitIdle() const noexcept;
  // The most device memory hairpipe may hold at once (0: no cap but the heaps).
  void setDeviceMemoryBudget(VkDeviceSize bytes) noexcept;
  // Bytes of device memory hairpipe's buffers and images hold now.
  std::uint64_t allocatedBytes() const noexcept;

 private:
  friend struct Access;  // hairpipe's implementation
  explicit Context(std::unique_ptr<hp::vk::Context> impl) noexcept;
  std::unique_ptr<hp::vk::Context> impl_;
};

// The instance version, device version, features, subgroup operations and queue capabilities hairpipe needs,
// one per line.
Result<std::vector<std::string>> requirements() noexcept;
// Why this physical device cannot run hairpipe (an empty list: it can), through the application's loader.
Result<std::vector<std::string>> unfitReasons(PFN_vkGetInstanceProcAddr getInstanceProcAddr, VkInstance instance,
                                      VkPhysicalDevice physicalDevice) noexcept;
}  // namespace hairpipe
