// hairpipe::Context and the device queries of the public API, over hp::vk::Context.
#include "compute/api/access.h"
#include "engine/vk/device_probe.h"

namespace hairpipe {
Context::Context(std::unique_ptr<hp::vk::Context> impl) noexcept : impl_(std::move(impl)) {}
Context::Context(Context&&) noexcept = default;
Context& Context::operator=(Context&&) noexcept = default;
Context::~Context() = default;

Result<Context> Context::adopt(const DeviceHandles& d) noexcept {
  return guarded<Context>("hairpipe::Context::adopt", [&] {
    return Access::makeContext(hp::vk::Context::adopt(d));
  });
}

Result<Context> Context::createHeadless(const HeadlessOptions& options) noexcept {
  return guarded<Context>("hairpipe::Context::createHeadless", [&] {
    hp::vk::ContextOptions o;
    o.validation = options.validation;
    o.device = options.device;
    return Access::makeContext(hp::vk::Context::createHeadless(o));
  });
}

// A moved-from Context answers with null handles, an empty name, zero bytes, and failures.
VkInstance Context::instance() const noexcept { return impl_ ? impl_->instance() : VK_NULL_HANDLE; }
VkPhysicalDevice Context::physicalDevice() const noexcept { return impl_ ? impl_->physicalDevice() : VK_NULL_HANDLE; }
VkDevice Context::device() const noexcept { return impl_ ? impl_->device() : VK_NULL_HANDLE; }
VkQueue Context::queue() const noexcept { return impl_ ? impl_->queue() : VK_NULL_HANDLE; }
std::uint32_t Context::queueFamily() const noexcept { return impl_ ? impl_->queueFamily() : 0; }
const char* Context::deviceName() const noexcept { return impl_ ? impl_->properties().deviceName : ""; }

Result<std::vector<std::string>> Context::validationMessages() const noexcept {
  return guarded<std::vector<std::string>>("hairpipe::Context::validationMessages", [&] {
    std::vector<std::string> out;
    for (const hp::vk::ValidationMessage& m : Access::context(*this).sharedValidationLog()->messages())
      out.push_back(m.idName + ": " + m.text);
    return out;
  });
}

Status Context::waitIdle() const noexcept {
  return guardedStatus("hairpipe::Context::waitIdle", [&] { Access::context(*this).waitIdle(); });
}

void Context::setDeviceMemoryBudget(VkDeviceSize bytes) noexcept {
  if (impl_) impl_->setDeviceMemoryBudget(bytes);
}
std::uint64_t Context::allocatedBytes() const noexcept { return impl_ ? impl_->allocatedBytes() : 0; }

Result<std::vector<std::string>> requirements() noexcept {
  return guarded<std::vector<std::string>>("hairpipe::requirements", [] {
    const hp::vk::DeviceRequirements r = hp::vk::requirements();
    std::vector<std::string> out{"Vulkan " + std::to_string(VK_API_VERSION_MAJOR(r.apiVersion)) + "." +
                                 std::to_string(VK_API_VERSION_MINOR(r.apiVersion))};
    for (const std::string& f : r.features) out.push_back("feature " + f);
    for (const std::string& e : r.extensions) out.push_back("extension " + e);
    out.push_back(r.subgroups);
    out.push_back(r.queue);
    return out;
  });
}

Result<std::vector<std::string>> unfitReasons(PFN_vkGetInstanceProcAddr getInstanceProcAddr, VkInstance instance,
                                              VkPhysicalDevice physicalDevice) noexcept {
  return guarded<std::vector<std::string>>("hairpipe::unfitReasons", [&] {
    if (!getInstanceProcAddr || !instance || !physicalDevice)
      throw hp::Error("getInstanceProcAddr, instance and physicalDevice must be set");
    hp::vk::loadInstanceFunctions(getInstanceProcAddr, instance);
    return hp::vk::unfitReasons(physicalDevice);
  });
}
}  // namespace hairpipe
