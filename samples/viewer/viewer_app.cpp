#include "samples/viewer/viewer_app.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>

#include <chrono>
#include <cstring>
#include <iostream>
#include <memory>

#include "engine/core/error.h"
#include "compute/raster/camera.h"
#include "engine/vk/barriers.h"
#include "engine/vk/buffer.h"
#include "engine/vk/check.h"
#include "engine/vk/context.h"
#include "engine/vk/fault_injection.h"
#include "samples/tools/interrupt_flag.h"
#include "samples/tools/png_file.h"
#include "samples/tools/character_clip.h"
#include "samples/tools/simulation_driver.h"
#include "samples/viewer/viewer_device.h"
#include "samples/viewer/viewer_panel.h"
#include "samples/viewer/window.h"

namespace hp::viewer {
namespace {
// Device losses in a row (no frame presented in between) after which the viewer gives up.
constexpr std::uint32_t kMaxLossesInARow = 3;

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

class Viewer {
 public:
  Viewer(const ViewerOptions& options, const HairAsset& asset);
  ViewerReport run();

 private:
  void frameStep();
  void armScriptedFault();
  void startDevice();
  void dropLostDevice(const vk::DeviceLost& loss);
  bool waitForSize();
  void applyPanel(const PanelChanges& changes);
  HeadMotion nextMotion();
  void record(FrameSlot& slot, std::uint32_t image, std::uint32_t slotIndex, bool screenshot);
  void blitAndOverlay(VkCommandBuffer cmd, std::uint32_t image, std::uint32_t slotIndex, bool screenshot);
  void submit(FrameSlot& slot, std::uint32_t image);
  void saveScreenshot();
  DrawView makeView();
  bool running() const {
    return !window_.shouldClose() && !state_.close && !interruptRequested() &&  // Ctrl-C in its terminal
           (options_.frames == 0 || frame_ < options_.frames);
  }

  const ViewerOptions& options_;
  const HairAsset& asset_;
  Window window_;
  ViewState state_;
  Tunables tunables_;
  Input input_;
  std::unique_ptr<ImGuiSession> imgui_;
  std::unique_ptr<ViewerDevice> gpu_;  // after the window and ImGui: destroyed before them
  PanelStatus status_;
  float headRadius_ = 1.0f;
  double animationTime_ = 0.0;
  CharacterClip clip_;  // --animate clip:NAME: the character's clip (its own clock: animationTime_)
  glm::mat4 head_{1.0f};
  std::uint64_t frame_ = 0;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
  std::size_t nextFault_ = 0;
  ViewerReport report_;
  std::uint32_t lossesInARow_ = 0;
  PanelChanges edited_;  // every kind of setting the user changed: applied again on a new device
  bool recreate_ = false;
  bool windOn_ = false;
};

Viewer::Viewer(const ViewerOptions& options, const HairAsset& asset)
    : options_(options),
      asset_(asset),
      window_(options.request.scene.render.width, options.request.scene.render.height, "hairpipe view"),
      state_(ViewState::fromScene(options.request.scene)),
      headRadius_(assetHeadRadius(asset)) {
  const RenderRequest& r = options.request;
  state_.panel = options.panel;
  state_.animation = r.animation;
  if (!r.characterClip.empty()) clip_ = characterClip(asset, r.characterClip);
  tunables_ = {r.scene.simulation, 4.0, r.scene.density.totalStrands, r.scene.material, r.lutMode, r.opacity, r.look,
               r.lod, r.exposure, editableLights(r.scene), r.scene.groom};
  input_.state = &state_;
  installInput(window_.handle(), input_);
  imgui_ = std::make_unique<ImGuiSession>(window_.handle());
  status_.startCollapsed = options.request.scene.render.width < 640;
}

// A new device with everything on it, set to the scene's settings and then to what the user changed.
void Viewer::startDevice() {
  gpu_ = std::make_unique<ViewerDevice>(options_, asset_, window_, report_.deviceLosses);
  applyPanel(edited_);
  status_.device = gpu_->ctx().properties().deviceName;
  status_.raster = rasterModeName(gpu_->raster());
  status_.strands = gpu_->hair().strands().layout().strandCount;
}

// Device loss: the lost device's validation messages are checked and everything on it destroyed; the
// frame loop then goes on with the same window and settings on a new device, the hair starting again
// from rest (its state was on the lost device). Lost again and again without a frame drawn: the end.
void Viewer::dropLostDevice(const vk::DeviceLost& loss) {
  ++report_.deviceLosses;
  if (++lossesInARow_ >= kMaxLossesInARow)
    throw Error(std::string(loss.what()) + ": the device was lost " + std::to_string(lossesInARow_) +
                " times in a row without a frame drawn; giving up");
  std::cerr << "hairpipe: " << loss.what() << "; starting again on a new device (the hair restarts from rest)\n";
  if (gpu_) cli::checkValidation(gpu_->ctx());
  gpu_.reset();
  recreate_ = false;
}

// Testing: the next scripted fault whose frame has come is armed once nothing else is.
void Viewer::armScriptedFault() {
  if (nextFault_ >= options_.faults.size() || vk::faultArmed()) return;
  const ScriptedFault& f = options_.faults[nextFault_];
  if (f.frame > frame_) return;
  vk::armFault(f.call, f.result);
  ++nextFault_;
}

// The window's size: a minimised window is not drawn (events are still handled while it waits); a new
// size or an out-of-date swapchain recreates the swapchain and targets.
bool Viewer::waitForSize() {
  if (options_.minimiseAt && frame_ == *options_.minimiseAt && report_.minimisedWaits == 0)
    window_.minimiseFor(options_.minimiseSeconds);
  if (window_.minimised()) {
    ++report_.minimisedWaits;
    window_.waitWhileMinimised();
  }
  if (window_.shouldClose()) return false;
  const VkExtent2D fb = window_.framebufferSize(), cur = gpu_->swapchain().extent();
  if (!recreate_ && fb.width == cur.width && fb.height == cur.height) return true;
  gpu_->ctx().waitIdle();
  gpu_->swapchain().recreate(fb);
  gpu_->recreateTargets();
  recreate_ = false;
  ++report_.swapchainRecreations;
  return true;
}

void Viewer::applyPanel(const PanelChanges& c) {
  HairSystem& hair = gpu_->hair();
  try {
    if (c.simulation) {
      SimulationParams p = tunables_.simulation;
      p.windStrength = state_.wind ? tunables_.windStrength : 0.0;
      hair.instance().setSimulation(p);
    }
    if (c.opacity) hair.renderer().setOpacityTuning(tunables_.opacity);
    if (c.look) hair.setLook(tunables_.look);
    if (c.lod) hair.instance().setLod(tunables_.lod);
    if (c.groom) hair.setGroom(tunables_.groom);
    if (c.material) hair.setMaterial(tunables_.material, tunables_.lutMode);
    if (c.density) {
      DensityOptions d = options_.request.scene.density;
      d.mode = DensityOptions::Mode::Total;
      d.totalStrands = tunables_.density;
      d.validate();
      hair.setStrands(buildInterpolationTopology(asset_.guides.roots(), asset_.topology.triangles, d));
      status_.strands = hair.strands().layout().strandCount;
    }
    status_.error.clear();
  } catch (const vk::DeviceLost&) {
    throw;  // not a refused setting: the frame loop starts again on a new device
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
  if (clip_.clip) poseCharacter(gpu_->hair().simulation(), clip_, animationTime_, to);
  return motion;
}

DrawView Viewer::makeView() {
  DrawView v;
  v.extent = gpu_->targets().extent();
  v.camera = orbitCamera(state_.camera, float(v.extent.width) / float(v.extent.height));
  if (!tunables_.lights.empty()) state_.steer(tunables_.lights.front());  // the light drag turns the first
  v.lights.clear();
  for (const EditedLight& l : tunables_.lights) v.lights.push_back(l.light);
  for (const LightSpec& l : options_.request.environmentLights)  // the panel's lights first, up to the limit
    if (v.lights.size() < kMaxSceneLights) v.lights.push_back(l);
  v.headToWorld = head_;
  return v;
}

void Viewer::blitAndOverlay(VkCommandBuffer cmd, std::uint32_t image, std::uint32_t slotIndex, bool screenshot) {
  const vk::Context& ctx = gpu_->ctx();
  Swapchain& swapchain = gpu_->swapchain();
  const VkImage display = gpu_->targets().display().handle(), target = swapchain.image(image);
  const VkExtent2D e = swapchain.extent();
  vk::imageBarrier(ctx, cmd, display, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment, vk::ImageUse::TransferSrc);
  vk::imageBarrier(ctx, cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::SwapchainAcquired, vk::ImageUse::TransferDst);
  VkImageBlit region{};
  region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.srcOffsets[1] = region.dstOffsets[1] = {std::int32_t(e.width), std::int32_t(e.height), 1};
  vkCmdBlitImage(cmd, display, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                 &region, VK_FILTER_NEAREST);
  // Back to what the next frame's tonemap transition expects (it discards from a colour attachment).
  vk::imageBarrier(ctx, cmd, display, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::TransferSrc, vk::ImageUse::ColorAttachment);
  vk::imageBarrier(ctx, cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::TransferDst, vk::ImageUse::ColorAttachment);
  VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  color.imageView = swapchain.view(image);
  color.imageLayout = vk::imageLayout(vk::ImageUse::ColorAttachment);
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, e};
  info.layerCount = 1;
  info.colorAttachmentCount = 1;
  info.pColorAttachments = &color;
  vkCmdBeginRendering(cmd, &info);
  gpu_->overlay().draw(cmd, slotIndex, *ImGui::GetDrawData(), e);
  vkCmdEndRendering(cmd);
  if (!screenshot) {
    vk::imageBarrier(ctx, cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment, vk::ImageUse::Present);
    return;
  }
  vk::imageBarrier(ctx, cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment, vk::ImageUse::TransferSrc);
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {e.width, e.height, 1};
  vkCmdCopyImageToBuffer(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, gpu_->screenshot().handle(), 1, &copy);
  vk::bufferBarrier(ctx, cmd, gpu_->screenshot().handle(), vk::BufferUse::TransferDst, vk::BufferUse::HostRead);
  vk::imageBarrier(ctx, cmd, target, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::TransferSrc, vk::ImageUse::Present);
}

void Viewer::record(FrameSlot& slot, std::uint32_t image, std::uint32_t slotIndex, bool screenshot) {
  VkCommandBuffer cmd = slot.cmd;
  HP_VK_CHECK(vkResetCommandBuffer(cmd, 0));
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  HP_VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
  vk::GpuProfiler& prof = *slot.profiler;
  prof.reset(cmd);
  HairSystem& hair = gpu_->hair();
  // Paused, the hair still takes one step where its strands are new (a density change, a restarted device):
  // the Renderer draws no strands a recordUpdate has not computed.
  if (!state_.paused || hair.needsUpdate()) hair.recordUpdate(cmd, nextMotion(), &prof);
  const DrawView view = makeView();
  hair.recordPrepareDraw(cmd, view, &prof);
  gpu_->targets().record(cmd, hair, view, tunables_.exposure, &prof);
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
  signal.semaphore = gpu_->swapchain().rendered(image);
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
  HP_VK_CHECK(vkQueueSubmit2(gpu_->ctx().queue(), 1, &info, slot.fence));
  slot.submitted = true;
}

// The swapchain image as it was presented (panel included), swizzled to RGBA when it is BGRA.
void Viewer::saveScreenshot() {
  gpu_->ctx().waitIdle();
  const vk::Buffer& shot = gpu_->screenshot();
  shot.invalidate();
  const VkExtent2D e = gpu_->swapchain().extent();
  std::vector<std::uint8_t> rgba(std::size_t(e.width) * e.height * 4);
  std::memcpy(rgba.data(), shot.mapped(), rgba.size());
  const VkFormat f = gpu_->swapchain().format();
  if (f == VK_FORMAT_B8G8R8A8_SRGB || f == VK_FORMAT_B8G8R8A8_UNORM)
    for (std::size_t i = 0; i < rgba.size(); i += 4) std::swap(rgba[i], rgba[i + 2]);
  for (std::size_t i = 3; i < rgba.size(); i += 4) rgba[i] = 255;  // opaque, whatever the surface's alpha
  writePng(options_.screenshot, e.width, e.height, 4, rgba);
}

// One pass of the frame loop: usually a frame drawn and presented; none while the swapchain is out of date.
void Viewer::frameStep() {
  glfwPollEvents();
  armScriptedFault();
  if (options_.resizeAt && frame_ == *options_.resizeAt)
    glfwSetWindowSize(window_.handle(), int(options_.resizeTo.width), int(options_.resizeTo.height));
  const std::uint32_t slotIndex = std::uint32_t(frame_ % kFramesInFlight);
  FrameSlot& slot = gpu_->slot(slotIndex);
  HP_VK_CHECK(vkWaitForFences(gpu_->ctx().device(), 1, &slot.fence, VK_TRUE, UINT64_MAX));
  if (slot.submitted) status_.passTimes = slot.profiler->results();
  if (!waitForSize()) return;
  std::uint32_t image = 0;
  if (gpu_->swapchain().acquire(slot.acquired, image) == Swapchain::Status::OutOfDate) {
    recreate_ = true;  // nothing was signalled: the slot's semaphore and fence stay as they are
    return;
  }
  HP_VK_CHECK(vkResetFences(gpu_->ctx().device(), 1, &slot.fence));
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const PanelChanges changes = drawPanel(tunables_, state_, status_);
  ImGui::Render();
  PanelChanges apply = changes;
  apply.simulation |= state_.wind != windOn_;  // W toggles it outside the panel
  windOn_ = state_.wind;
  applyPanel(apply);
  edited_ = {edited_.simulation || apply.simulation, edited_.density || apply.density,
             edited_.material || apply.material, edited_.opacity || apply.opacity, edited_.look || apply.look,
             edited_.lod || apply.lod, edited_.groom || apply.groom};
  const bool shot = !options_.screenshot.empty() && options_.frames > 0 && frame_ + 1 == options_.frames;
  record(slot, image, slotIndex, shot);
  submit(slot, image);
  if (gpu_->swapchain().present(image) != Swapchain::Status::Ok) recreate_ = true;
  const auto now = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
  status_.frameMs = frame_ == 0 ? ms : 0.9 * status_.frameMs + 0.1 * ms;
  last_ = now;
  ++frame_;
  lossesInARow_ = 0;
  if (shot) saveScreenshot();
}

ViewerReport Viewer::run() {
  while (running()) {
    try {
      if (!gpu_) startDevice();
      frameStep();
    } catch (const vk::DeviceLost& loss) {
      dropLostDevice(loss);
    }
  }
  vk::disarmFault();  // a scripted fault that never fired ends with the run
  report_.frames = std::uint32_t(frame_);
  if (!gpu_) return report_;  // closed right after a device loss
  gpu_->ctx().waitIdle();
  report_.extent = gpu_->swapchain().extent();
  report_.device = gpu_->ctx().properties().deviceName;
  report_.raster = rasterModeName(gpu_->raster());
  cli::checkValidation(gpu_->ctx());
  return report_;
}
}  // namespace

ViewerReport runViewer(const ViewerOptions& options, const HairAsset& asset) {
  Viewer viewer(options, asset);
  return viewer.run();
}
}  // namespace hp::viewer
