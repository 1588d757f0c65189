#include "samples/viewer/viewer_app.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <chrono>
#include <cstring>
#include <memory>

#include "engine/error.h"
#include "engine/render/camera.h"
#include "engine/vk/barriers.h"
#include "engine/vk/buffer.h"
#include "engine/vk/check.h"
#include "engine/vk/context.h"
#include "samples/tools/offscreen_renderer.h"
#include "samples/tools/png_file.h"
#include "samples/tools/simulation_driver.h"
#include "samples/viewer/imgui_overlay.h"
#include "samples/viewer/swapchain.h"
#include "samples/viewer/viewer_panel.h"
#include "samples/viewer/window.h"

namespace hp::viewer {
namespace {
constexpr std::uint32_t kFramesInFlight = 2;
constexpr std::uint32_t kMaxScopes = 24;

// What one frame in flight owns: its command buffer, fence, acquire semaphore and timestamps.
struct FrameSlot {
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  VkSemaphore acquired = VK_NULL_HANDLE;
  std::unique_ptr<vk::GpuProfiler> profiler;
  bool submitted = false;
};

// Mouse and keys from GLFW into the ViewState, unless the panel has them.
struct Input {
  ViewState* state = nullptr;
  double lastX = 0.0, lastY = 0.0;
  bool orbiting = false, lighting = false;
};

Key keyOf(int key) {
  switch (key) {
    case GLFW_KEY_N: return Key::Nod;
    case GLFW_KEY_T: return Key::Turn;
    case GLFW_KEY_S: return Key::Shake;
    case GLFW_KEY_W: return Key::Wind;
    case GLFW_KEY_SPACE: return Key::Pause;
    case GLFW_KEY_F1: case GLFW_KEY_TAB: return Key::Panel;
    case GLFW_KEY_ESCAPE: case GLFW_KEY_Q: return Key::Close;
    default: return Key::Other;
  }
}

void installInput(GLFWwindow* window, Input& input) {
  glfwSetWindowUserPointer(window, &input);
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int button, int action, int mods) {
    auto& in = *static_cast<Input*>(glfwGetWindowUserPointer(w));
    const bool press = action == GLFW_PRESS && !ImGui::GetIO().WantCaptureMouse;
    if (button == GLFW_MOUSE_BUTTON_LEFT) {
      in.lighting = press && (mods & GLFW_MOD_SHIFT);
      in.orbiting = press && !(mods & GLFW_MOD_SHIFT);
    } else if (button == GLFW_MOUSE_BUTTON_RIGHT) {
      in.lighting = press;
    }
    glfwGetCursorPos(w, &in.lastX, &in.lastY);
  });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double x, double y) {
    auto& in = *static_cast<Input*>(glfwGetWindowUserPointer(w));
    if (in.orbiting || in.lighting) in.state->drag(float(x - in.lastX), float(y - in.lastY), in.lighting);
    in.lastX = x;
    in.lastY = y;
  });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double dy) {
    if (!ImGui::GetIO().WantCaptureMouse) static_cast<Input*>(glfwGetWindowUserPointer(w))->state->scroll(float(dy));
  });
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int, int action, int) {
    if (action == GLFW_PRESS && !ImGui::GetIO().WantCaptureKeyboard)
      static_cast<Input*>(glfwGetWindowUserPointer(w))->state->key(keyOf(key));
  });
}

// Dear ImGui's context and GLFW backend (Debian's imgui_impl_glfw.cpp), ended in reverse order.
struct ImGuiSession {
  explicit ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // never write imgui.ini into the working folder
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForVulkan(window, true);  // chains to the callbacks installed before
  }
  ~ImGuiSession() {
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
};

void setName(const vk::Context& ctx, VkObjectType type, const void* handle, const std::string& name) {
  ctx.setName(type, reinterpret_cast<std::uint64_t>(handle), name);
}

class Viewer {
 public:
  Viewer(const ViewerOptions& options, const HairAsset& asset);
  ~Viewer();
  ViewerReport run();

 private:
  void createSlots();
  void recreateTargets();
  bool waitForSize();
  void applyPanel(const PanelChanges& changes);
  HeadMotion nextMotion();
  void record(FrameSlot& slot, std::uint32_t image, std::uint32_t slotIndex, bool screenshot);
  void blitAndOverlay(VkCommandBuffer cmd, std::uint32_t image, std::uint32_t slotIndex, bool screenshot);
  void submit(FrameSlot& slot, std::uint32_t image);
  void saveScreenshot();
  DrawView makeView() const;

  const ViewerOptions& options_;
  const HairAsset& asset_;
  Window window_;
  std::unique_ptr<vk::Context> ctx_;
  std::unique_ptr<Swapchain> swapchain_;
  RasterMode raster_;
  std::unique_ptr<render::OffscreenRenderer> targets_;
  std::unique_ptr<HairSystem> hair_;
  ViewState state_;
  Tunables tunables_;
  Input input_;
  std::unique_ptr<ImGuiSession> imgui_;
  std::unique_ptr<ImGuiOverlay> overlay_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  FrameSlot slots_[kFramesInFlight];
  vk::Buffer screenshot_;
  PanelStatus status_;
  float headRadius_ = 1.0f;
  double animationTime_ = 0.0;
  glm::mat4 head_{1.0f};
  std::uint32_t recreations_ = 0;
  bool recreate_ = false;
  bool windOn_ = false;
};

vk::ContextOptions windowExtensions() {
  vk::ContextOptions o;
  o.instanceExtensions = Window::requiredInstanceExtensions();
  o.deviceExtensions = {VK_KHR_SWAPCHAIN_EXTENSION_NAME};
  return o;
}

Viewer::Viewer(const ViewerOptions& options, const HairAsset& asset)
    : options_(options),
      asset_(asset),
      window_(options.request.scene.render.width, options.request.scene.render.height, "hairpipe view"),
      ctx_(cli::createContext(options.scene, windowExtensions())),
      swapchain_(std::make_unique<Swapchain>(*ctx_, window_.createSurface(ctx_->instance()), window_.framebufferSize())),
      raster_(resolveRasterMode(options.request.scene.render.raster, ctx_->properties().deviceType)),
      state_(ViewState::fromScene(options.request.scene)),
      headRadius_(assetHeadRadius(asset)) {
  const RenderRequest& r = options.request;
  state_.panel = options.panel;
  state_.animation = r.animation;
  tunables_ = {r.scene.simulation, 4.0, r.scene.density.totalStrands, r.scene.material, r.lutMode, r.opacity, r.look,
               r.exposure};
  recreateTargets();
  RenderRequest resolved = r;
  resolved.scene.render.raster = raster_;
  hair_ = std::make_unique<HairSystem>(*ctx_, asset, systemSettings(resolved, targets_->formats()));
  targets_->attach(*hair_);
  input_.state = &state_;
  installInput(window_.handle(), input_);
  imgui_ = std::make_unique<ImGuiSession>(window_.handle());
  overlay_ = std::make_unique<ImGuiOverlay>(*ctx_, swapchain_->format(), kFramesInFlight);
  createSlots();
  status_.device = ctx_->properties().deviceName;
  status_.raster = rasterModeName(raster_);
  status_.strands = hair_->strands().layout().strandCount;
  status_.startCollapsed = swapchain_->extent().width < 640;
}

Viewer::~Viewer() {
  // Everything the GPU may still use is released after it is done (device loss included: the
  // wait then fails, and the destruction of a lost device's objects is still valid).
  if (ctx_) vkDeviceWaitIdle(ctx_->device());
  for (auto& s : slots_) {
    if (s.fence) vkDestroyFence(ctx_->device(), s.fence, nullptr);
    if (s.acquired) vkDestroySemaphore(ctx_->device(), s.acquired, nullptr);
  }
  if (pool_) vkDestroyCommandPool(ctx_->device(), pool_, nullptr);
}

void Viewer::createSlots() {
  VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pi.queueFamilyIndex = ctx_->queueFamily();
  HP_VK_CHECK(vkCreateCommandPool(ctx_->device(), &pi, nullptr, &pool_));
  setName(*ctx_, VK_OBJECT_TYPE_COMMAND_POOL, pool_, "viewer frames");
  for (std::uint32_t i = 0; i < kFramesInFlight; ++i) {
    FrameSlot& s = slots_[i];
    const std::string name = "viewer frame slot " + std::to_string(i);
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

// Offscreen targets at the swapchain's size (after a wait for the device: nothing in flight uses them).
void Viewer::recreateTargets() {
  const VkExtent2D e = swapchain_->extent();
  const RenderSpec& spec = options_.request.scene.render;
  targets_ = std::make_unique<render::OffscreenRenderer>(*ctx_, e.width, e.height, spec.msaa, raster_);
  if (hair_) targets_->attach(*hair_);
  screenshot_ = vk::Buffer(*ctx_, VkDeviceSize(e.width) * e.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           vk::MemoryKind::Readback, "viewer screenshot readback");
}

// A minimised window has a zero-size framebuffer: wait for events until it has a size again.
bool Viewer::waitForSize() {
  VkExtent2D fb = window_.framebufferSize();
  while ((fb.width == 0 || fb.height == 0) && !window_.shouldClose()) {
    glfwWaitEvents();
    fb = window_.framebufferSize();
  }
  if (window_.shouldClose()) return false;
  const VkExtent2D cur = swapchain_->extent();
  if (!recreate_ && fb.width == cur.width && fb.height == cur.height) return true;
  ctx_->waitIdle();
  swapchain_->recreate(fb);
  recreateTargets();
  recreate_ = false;
  ++recreations_;
  return true;
}

void Viewer::applyPanel(const PanelChanges& c) {
  try {
    if (c.simulation) {
      SimulationParams p = tunables_.simulation;
      p.windStrength = state_.wind ? tunables_.windStrength : 0.0;
      hair_->instance().setSimulation(p);
    }
    if (c.opacity) hair_->renderer().setOpacityTuning(tunables_.opacity);
    if (c.look) hair_->setLook(tunables_.look);
    if (c.material) hair_->setMaterial(tunables_.material, tunables_.lutMode);
    if (c.density) {
      DensityOptions d = options_.request.scene.density;
      d.mode = DensityOptions::Mode::Total;
      d.totalStrands = tunables_.density;
      d.validate();
      hair_->setStrands(buildInterpolationTopology(asset_.guides.roots(), asset_.topology.triangles, d));
      status_.strands = hair_->strands().layout().strandCount;
    }
    status_.error.clear();
  } catch (const Error& e) {
    status_.error = e.what();
  }
}

// The head's motion over the next step. A new animation starts its own clock at 0 (every animation
// is at rest there); the jump from wherever the head was is carried rigidly (a teleport).
HeadMotion Viewer::nextMotion() {
  const bool jump = state_.animationChanged;
  if (jump) animationTime_ = 0.0;
  state_.animationChanged = false;
  const glm::mat4 to = headTransformAt(state_.animation, animationTime_ + tunables_.simulation.dt, headRadius_);
  const HeadMotion motion{head_, to, animationTime_, jump};
  animationTime_ += tunables_.simulation.dt;
  head_ = to;
  return motion;
}

DrawView Viewer::makeView() const {
  DrawView v;
  v.extent = targets_->extent();
  v.camera = orbitCamera(state_.camera, float(v.extent.width) / float(v.extent.height));
  v.light = options_.request.scene.light;
  v.light.type = LightSpec::Type::Directional;
  v.light.direction = state_.lightDirection();
  v.headToWorld = head_;
  return v;
}

void Viewer::blitAndOverlay(VkCommandBuffer cmd, std::uint32_t image, std::uint32_t slotIndex, bool screenshot) {
  const VkImage display = targets_->display().handle(), target = swapchain_->image(image);
  const VkExtent2D e = swapchain_->extent();
  vk::imageBarrier(*ctx_, cmd, display, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment, vk::ImageUse::TransferSrc);
  vk::imageBarrier(*ctx_, cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::SwapchainAcquired, vk::ImageUse::TransferDst);
  VkImageBlit region{};
  region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.srcOffsets[1] = region.dstOffsets[1] = {std::int32_t(e.width), std::int32_t(e.height), 1};
  vkCmdBlitImage(cmd, display, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                 &region, VK_FILTER_NEAREST);
  // Back to what the next frame's tonemap transition expects (it discards from a colour attachment).
  vk::imageBarrier(*ctx_, cmd, display, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::TransferSrc, vk::ImageUse::ColorAttachment);
  vk::imageBarrier(*ctx_, cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::TransferDst, vk::ImageUse::ColorAttachment);
  VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  color.imageView = swapchain_->view(image);
  color.imageLayout = vk::imageLayout(vk::ImageUse::ColorAttachment);
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, e};
  info.layerCount = 1;
  info.colorAttachmentCount = 1;
  info.pColorAttachments = &color;
  vkCmdBeginRendering(cmd, &info);
  overlay_->draw(cmd, slotIndex, *ImGui::GetDrawData(), e);
  vkCmdEndRendering(cmd);
  if (!screenshot) {
    vk::imageBarrier(*ctx_, cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment, vk::ImageUse::Present);
    return;
  }
  vk::imageBarrier(*ctx_, cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment, vk::ImageUse::TransferSrc);
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {e.width, e.height, 1};
  vkCmdCopyImageToBuffer(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, screenshot_.handle(), 1, &copy);
  vk::bufferBarrier(*ctx_, cmd, screenshot_.handle(), vk::BufferUse::TransferDst, vk::BufferUse::HostRead);
  vk::imageBarrier(*ctx_, cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::TransferSrc, vk::ImageUse::Present);
}

void Viewer::record(FrameSlot& slot, std::uint32_t image, std::uint32_t slotIndex, bool screenshot) {
  VkCommandBuffer cmd = slot.cmd;
  HP_VK_CHECK(vkResetCommandBuffer(cmd, 0));
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  HP_VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
  vk::GpuProfiler& prof = *slot.profiler;
  prof.reset(cmd);
  if (!state_.paused) hair_->recordUpdate(cmd, nextMotion(), &prof);
  const DrawView view = makeView();
  hair_->recordPrepareDraw(cmd, view, &prof);
  targets_->record(cmd, *hair_, view, tunables_.exposure, &prof);
  prof.begin(cmd, "present + ui");
  blitAndOverlay(cmd, image, slotIndex, screenshot);
  prof.end(cmd);
  HP_VK_CHECK(vkEndCommandBuffer(cmd));
}

void Viewer::submit(FrameSlot& slot, std::uint32_t image) {
  VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  wait.semaphore = slot.acquired;
  wait.stageMask = vk::kSwapchainWaitStages;
  VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  signal.semaphore = swapchain_->rendered(image);
  signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkCommandBufferSubmitInfo cb{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cb.commandBuffer = slot.cmd;
  VkSubmitInfo2 info{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  info.waitSemaphoreInfoCount = 1;
  info.pWaitSemaphoreInfos = &wait;
  info.commandBufferInfoCount = 1;
  info.pCommandBufferInfos = &cb;
  info.signalSemaphoreInfoCount = 1;
  info.pSignalSemaphoreInfos = &signal;
  HP_VK_CHECK(vkQueueSubmit2(ctx_->queue(), 1, &info, slot.fence));
  slot.submitted = true;
}

// The swapchain image as it was presented (panel included), swizzled to RGBA when it is BGRA.
void Viewer::saveScreenshot() {
  ctx_->waitIdle();
  screenshot_.invalidate();
  const VkExtent2D e = swapchain_->extent();
  std::vector<std::uint8_t> rgba(std::size_t(e.width) * e.height * 4);
  std::memcpy(rgba.data(), screenshot_.mapped(), rgba.size());
  const VkFormat f = swapchain_->format();
  if (f == VK_FORMAT_B8G8R8A8_SRGB || f == VK_FORMAT_B8G8R8A8_UNORM)
    for (std::size_t i = 0; i < rgba.size(); i += 4) std::swap(rgba[i], rgba[i + 2]);
  for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;  // opaque, whatever the surface's alpha
  writePng(options_.screenshot, e.width, e.height, 4, rgba);
}

ViewerReport Viewer::run() {
  ViewerReport report;
  std::uint64_t frame = 0;
  auto last = std::chrono::steady_clock::now();
  while (!window_.shouldClose() && !state_.close && (options_.frames == 0 || frame < options_.frames)) {
    glfwPollEvents();
    if (options_.resizeAt && frame == *options_.resizeAt)
      glfwSetWindowSize(window_.handle(), int(options_.resizeTo.width), int(options_.resizeTo.height));
    const std::uint32_t slotIndex = std::uint32_t(frame % kFramesInFlight);
    FrameSlot& slot = slots_[slotIndex];
    HP_VK_CHECK(vkWaitForFences(ctx_->device(), 1, &slot.fence, VK_TRUE, UINT64_MAX));
    if (slot.submitted) status_.passTimes = slot.profiler->results();
    if (!waitForSize()) break;
    std::uint32_t image = 0;
    if (swapchain_->acquire(slot.acquired, image) == Swapchain::Status::OutOfDate) {
      recreate_ = true;  // nothing was signalled: the slot's semaphore and fence stay as they are
      continue;
    }
    HP_VK_CHECK(vkResetFences(ctx_->device(), 1, &slot.fence));
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const PanelChanges changes = drawPanel(tunables_, state_, status_);
    ImGui::Render();
    PanelChanges apply = changes;
    apply.simulation |= state_.wind != windOn_;  // W toggles it outside the panel
    windOn_ = state_.wind;
    applyPanel(apply);
    const bool shot = !options_.screenshot.empty() && options_.frames > 0 && frame + 1 == options_.frames;
    record(slot, image, slotIndex, shot);
    submit(slot, image);
    if (swapchain_->present(image) != Swapchain::Status::Ok) recreate_ = true;
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - last).count();
    status_.frameMs = frame == 0 ? ms : 0.9 * status_.frameMs + 0.1 * ms;
    last = now;
    ++frame;
    if (shot) saveScreenshot();
  }
  ctx_->waitIdle();
  report.frames = std::uint32_t(frame);
  report.swapchainRecreations = recreations_;
  report.extent = swapchain_->extent();
  report.device = ctx_->properties().deviceName;
  report.raster = rasterModeName(raster_);
  cli::checkValidation(*ctx_);
  return report;
}
}  // namespace

ViewerReport runViewer(const ViewerOptions& options, const HairAsset& asset) {
  Viewer viewer(options, asset);
  return viewer.run();
}
}  // namespace hp::viewer
