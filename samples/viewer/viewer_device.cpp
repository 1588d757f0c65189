#include "samples/viewer/viewer_device.h"

#include <string>

#include "engine/vk/check.h"
#include "samples/cli/scene_options.h"
#include "samples/tools/character_clip.h"
#include "shaders/shared/opacity.h"

namespace hp::viewer {
namespace {
constexpr std::uint32_t kMaxScopes = 64;  // the passes (the raster bin with its 4 steps) and six per shadowed light (up to 4)

vk::ContextOptions windowExtensions() {
  vk::ContextOptions o;
  o.instanceExtensions = Window::requiredInstanceExtensions();
  o.deviceExtensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  return o;
}

void setName(const vk::Context& ctx, VkObjectType type, const void* handle, const std::string& name) {
  ctx.setName(type, reinterpret_cast<std::uint64_t>(handle), name);
}
}  // namespace

ViewerDevice::ViewerDevice(const ViewerOptions& options, const HairAsset& asset, const Window& window,
                           std::uint32_t generation)
    : options_(options),
      ctx_(cli::createContext(options.scene, windowExtensions())),
      swapchain_(std::make_unique<Swapchain>(*ctx_, window.createSurface(ctx_->instance()), window.framebufferSize())),
      raster_(resolveRasterMode(options.request.scene.render.raster, ctx_->properties().deviceType)) {
  try {
    recreateTargets();
    RenderRequest resolved = options.request;
    resolved.scene.render.raster = raster_;
    HairSystemSettings settings = systemSettings(resolved, targets_->formats());
    settings.shadowedLights = gpu::OPACITY_MAX_LIGHTS;  // the panel may add lights: every shadow slot from the start
    if (!options.request.characterClip.empty()) settings.scalp = characterScalp(asset);  // the clip's bones move the roots
    hair_ = std::make_unique<HairSystem>(*ctx_, asset, settings);
    targets_->attach(*hair_);
    overlay_ = std::make_unique<ImGuiOverlay>(*ctx_, swapchain_->format(), kFramesInFlight);
    createSlots(generation);
  } catch (...) {
    releaseSlots();  // the members made so far are destroyed by their own destructors
    throw;
  }
}

ViewerDevice::~ViewerDevice() { releaseSlots(); }

void ViewerDevice::releaseSlots() {
  vkDeviceWaitIdle(ctx_->device());  // its result is of no use here: lost or not, everything goes
  for (auto& s : slots_) {
    if (s.fence) vkDestroyFence(ctx_->device(), s.fence, nullptr);
    if (s.acquired) vkDestroySemaphore(ctx_->device(), s.acquired, nullptr);
    s = FrameSlot{};
  }
  if (pool_) vkDestroyCommandPool(ctx_->device(), pool_, nullptr);
  pool_ = VK_NULL_HANDLE;
}

void ViewerDevice::createSlots(std::uint32_t generation) {
  VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pi.queueFamilyIndex = ctx_->queueFamily();
  HP_VK_CHECK(vkCreateCommandPool(ctx_->device(), &pi, nullptr, &pool_));
  const std::string device = "viewer device " + std::to_string(generation);
  setName(*ctx_, VK_OBJECT_TYPE_COMMAND_POOL, pool_, device + " frames");
  for (std::uint32_t i = 0; i < kFramesInFlight; ++i) {
    FrameSlot& s = slots_[i];
    const std::string name = device + " frame slot " + std::to_string(i);
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = pool_;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    HP_VK_CHECK(vkAllocateCommandBuffers(ctx_->device(), &ai, &s.cmd));
    setName(*ctx_, VK_OBJECT_TYPE_COMMAND_BUFFER, s.cmd, name);
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    fi.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    HP_VK_CHECK(vkCreateFence(ctx_->device(), &fi, nullptr, &s.fence));
    setName(*ctx_, VK_OBJECT_TYPE_FENCE, s.fence, name);
    VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    HP_VK_CHECK(vkCreateSemaphore(ctx_->device(), &si, nullptr, &s.acquired));
    setName(*ctx_, VK_OBJECT_TYPE_SEMAPHORE, s.acquired, name + " acquired");
    s.profiler = std::make_unique<vk::GpuProfiler>(*ctx_, kMaxScopes, name);
  }
}

void ViewerDevice::recreateTargets() {
  const VkExtent2D e = swapchain_->extent();
  const RenderSpec& spec = options_.request.scene.render;
  targets_ = std::make_unique<render::OffscreenRenderer>(*ctx_, e.width, e.height, spec.msaa, raster_);
  if (hair_) targets_->attach(*hair_);
  screenshot_ = vk::Buffer(*ctx_, VkDeviceSize(e.width) * e.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           vk::MemoryKind::Readback, "viewer screenshot readback");
}
}  // namespace hp::viewer
