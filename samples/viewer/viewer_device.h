#pragma once
// Contract: everything the viewer holds on one Vulkan device: the context (instance + device), the
// window's surface and swapchain, hairpipe's HairSystem and offscreen targets at the swapchain's size,
// the Dear ImGui overlay, and per frame in flight a command buffer, fence, acquire semaphore and GPU
// timestamps. Made whole and dropped whole: after a device loss the viewer destroys it and makes a new
// one (the window, the ImGui context and the user's settings live outside it). The destructor waits for
// the device first (a lost device's wait fails; destroying its objects is still valid) and destroys in
// reverse order of creation. Construction throws hp::Error (vk::DeviceLost when the device is lost).
#include <cstdint>
#include <memory>

#include "samples/tools/hair_system.h"
#include "engine/vk/buffer.h"
#include "engine/vk/context.h"
#include "engine/vk/profiler.h"
#include "samples/tools/offscreen_renderer.h"
#include "samples/viewer/imgui_overlay.h"
#include "samples/viewer/swapchain.h"
#include "samples/viewer/viewer_app.h"
#include "samples/viewer/window.h"

namespace hp::viewer {
constexpr std::uint32_t kFramesInFlight = 2;

// What one frame in flight owns.
struct FrameSlot {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  VkSemaphore acquired = VK_NULL_HANDLE;
  std::unique_ptr<vk::GpuProfiler> profiler;
  bool submitted = false;
};

class ViewerDevice {
 public:
  // `generation` (0 for the first device, then one more per device loss) goes into the debug names.
  ViewerDevice(const ViewerOptions& options, const HairAsset& asset, const Window& window, std::uint32_t generation);
  ~ViewerDevice();
  ViewerDevice(const ViewerDevice&) = delete;
  ViewerDevice& operator=(const ViewerDevice&) = delete;

  // Offscreen targets and the screenshot buffer at the swapchain's size (the device must be idle).
  void recreateTargets();

  vk::Context& ctx() { return *ctx_; }
  Swapchain& swapchain() { return *swapchain_; }
  RasterMode raster() const { return raster_; }
  render::OffscreenRenderer& targets() { return *targets_; }
  HairSystem& hair() { return *hair_; }
  ImGuiOverlay& overlay() { return *overlay_; }
  FrameSlot& slot(std::uint32_t i) { return slots_[i]; }
  const vk::Buffer& screenshot() const { return screenshot_; }

 private:
  void createSlots(std::uint32_t generation);
  void releaseSlots();  // after a wait for the device

  const ViewerOptions& options_;
  std::unique_ptr<vk::Context> ctx_;
  std::unique_ptr<Swapchain> swapchain_;
  RasterMode raster_;
  std::unique_ptr<render::OffscreenRenderer> targets_;
  std::unique_ptr<HairSystem> hair_;
  std::unique_ptr<ImGuiOverlay> overlay_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  FrameSlot slots_[kFramesInFlight];
  vk::Buffer screenshot_;
};
}  // namespace hp::viewer
