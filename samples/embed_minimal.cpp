// A minimal embedding of hairpipe in an application that owns its Vulkan instance, device, queue,
// attachments and command buffers (ARCHITECTURE.md "Embedding contract"). The application:
//   1. creates its Vulkan 1.3 device with dynamicRendering + synchronization2 and a graphics+compute queue,
//   2. hands the handles to hp::vk::Context::adopt and creates one hp::Renderer for its attachment formats,
//   3. creates two hair instances: one whose lower scalp is skinned to a jaw/neck bone, one rigid head,
//   4. each frame records hairpipe's update, shadows and draw into ITS command buffer and ITS rendering,
//      with two frames in flight (a command buffer and fence per slot),
//   5. destroys hairpipe before its device.
// Usage: hairpipe_embed_minimal [--validation] [--frames N] [--out FILE.png]
#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#include <iostream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/error.h"
#include "engine/hair/default_head.h"
#include "engine/hair/head_sdf.h"
#include "engine/renderer.h"
#include "engine/shading/material_color.h"
#include "samples/tools/png_file.h"
#include "engine/sim/head_animation.h"
#include "engine/vk/barriers.h"
#include "engine/vk/check.h"
#include "engine/vk/context.h"
#include "engine/vk/image.h"
#include "engine/vk/transfer.h"

namespace {
constexpr std::uint32_t kWidth = 320, kHeight = 240;
constexpr VkFormat kColor = VK_FORMAT_R8G8B8A8_UNORM;  // the app's own choice of formats
constexpr VkFormat kDepth = VK_FORMAT_D32_SFLOAT;
constexpr std::uint32_t kFramesInFlight = 2;

std::uint32_t validationMessages = 0;
VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  std::cerr << "validation: " << data->pMessage << "\n";
  ++validationMessages;
  return VK_FALSE;
}

// Everything the application owns, created and destroyed by the application.
struct App {
  VkInstance instance = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  std::uint32_t family = 0;
  VkQueue queue = VK_NULL_HANDLE;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmds[kFramesInFlight] = {};
  VkFence fences[kFramesInFlight] = {};
  bool pending[kFramesInFlight] = {};

  void create(bool validation) {
    HP_VK_CHECK(volkInitialize());
    VkApplicationInfo appInfo{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    appInfo.pApplicationName = "embed_minimal";
    appInfo.apiVersion = VK_API_VERSION_1_3;
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* ext = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkInstanceCreateInfo ii{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ii.pApplicationInfo = &appInfo;
    ii.enabledLayerCount = validation ? 1 : 0;
    ii.ppEnabledLayerNames = &layer;
    ii.enabledExtensionCount = 1;
    ii.ppEnabledExtensionNames = &ext;
    HP_VK_CHECK(vkCreateInstance(&ii, nullptr, &instance));
    volkLoadInstance(instance);
    if (validation) {
      VkDebugUtilsMessengerCreateInfoEXT mi{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
      mi.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
      mi.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT;
      mi.pfnUserCallback = onMessage;
      HP_VK_CHECK(vkCreateDebugUtilsMessengerEXT(instance, &mi, nullptr, &messenger));
    }
    std::uint32_t count = 1;
    VkResult r = vkEnumeratePhysicalDevices(instance, &count, &physical);
    if ((r != VK_SUCCESS && r != VK_INCOMPLETE) || count == 0) throw hp::Error("no Vulkan device");
    std::uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, nullptr);
    std::vector<VkQueueFamilyProperties> props(families);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, props.data());
    while (family < families && (props[family].queueFlags & (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT)) !=
                                    (VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT))
      ++family;
    if (family == families) throw hp::Error("no graphics+compute queue");
    float priority = 1.0f;
    VkDeviceQueueCreateInfo qi{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qi.queueFamilyIndex = family;
    qi.queueCount = 1;
    qi.pQueuePriorities = &priority;
    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    v13.dynamicRendering = VK_TRUE;
    v13.synchronization2 = VK_TRUE;
    VkDeviceCreateInfo di{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &v13};
    di.queueCreateInfoCount = 1;
    di.pQueueCreateInfos = &qi;
    HP_VK_CHECK(vkCreateDevice(physical, &di, nullptr, &device));
    volkLoadDevice(device);
    vkGetDeviceQueue(device, family, 0, &queue);
    VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pi.queueFamilyIndex = family;
    HP_VK_CHECK(vkCreateCommandPool(device, &pi, nullptr, &pool));
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = pool;
    ai.commandBufferCount = kFramesInFlight;
    HP_VK_CHECK(vkAllocateCommandBuffers(device, &ai, cmds));
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    for (VkFence& f : fences) HP_VK_CHECK(vkCreateFence(device, &fi, nullptr, &f));
  }

  // The slot's previous frame (frame - kFramesInFlight) is done: its command buffer is free again.
  void waitSlot(std::uint32_t slot) {
    if (!pending[slot]) return;
    HP_VK_CHECK(vkWaitForFences(device, 1, &fences[slot], VK_TRUE, UINT64_MAX));
    HP_VK_CHECK(vkResetFences(device, 1, &fences[slot]));
    pending[slot] = false;
  }

  void submit(std::uint32_t slot) {
    VkCommandBufferSubmitInfo ci{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    ci.commandBuffer = cmds[slot];
    VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    si.commandBufferInfoCount = 1;
    si.pCommandBufferInfos = &ci;
    HP_VK_CHECK(vkQueueSubmit2(queue, 1, &si, fences[slot]));
    pending[slot] = true;
  }

  void destroy() {
    if (device) vkDeviceWaitIdle(device);
    for (VkFence f : fences)
      if (f) vkDestroyFence(device, f, nullptr);
    if (pool) vkDestroyCommandPool(device, pool, nullptr);
    if (device) vkDestroyDevice(device, nullptr);
    if (messenger) vkDestroyDebugUtilsMessengerEXT(instance, messenger, nullptr);
    if (instance) vkDestroyInstance(instance, nullptr);
  }
};

// One frame of the application: hairpipe's update and shadows, then the app's own rendering with
// hairpipe's draw inside it. Both frames in flight render into the same attachments, so each frame's
// transitions wait for the previous frame's writes (the *Discard uses) before discarding them.
void recordFrame(VkCommandBuffer cmd, hp::Renderer& renderer, std::uint64_t frame,
                 std::span<hp::HairInstance* const> heads, const hp::LightSpec& light, const hp::View& view,
                 const hp::vk::Image& color, const hp::vk::Image& depth) {
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  HP_VK_CHECK(vkBeginCommandBuffer(cmd, &bi));
  renderer.recordUpdate(cmd, frame, heads);
  renderer.recordShadows(cmd, frame, light, heads);
  hp::vk::imageBarrier(cmd, color.handle(), VK_IMAGE_ASPECT_COLOR_BIT, hp::vk::ImageUse::ColorAttachmentDiscard,
                       hp::vk::ImageUse::ColorAttachment);
  hp::vk::imageBarrier(cmd, depth.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, hp::vk::ImageUse::DepthAttachmentDiscard,
                       hp::vk::ImageUse::DepthAttachment);
  VkRenderingAttachmentInfo c{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  c.imageView = color.view();
  c.imageLayout = hp::vk::imageLayout(hp::vk::ImageUse::ColorAttachment);
  c.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  c.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  c.clearValue.color = {{0.2f, 0.25f, 0.3f, 1.0f}};
  VkRenderingAttachmentInfo d{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  d.imageView = depth.view();
  d.imageLayout = hp::vk::imageLayout(hp::vk::ImageUse::DepthAttachment);
  d.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  d.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  d.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
  ri.renderArea = {{0, 0}, {kWidth, kHeight}};
  ri.layerCount = 1;
  ri.colorAttachmentCount = 1;
  ri.pColorAttachments = &c;
  ri.pDepthAttachment = &d;
  vkCmdBeginRendering(cmd, &ri);
  renderer.recordDraw(cmd, frame, view, heads);
  vkCmdEndRendering(cmd);
  HP_VK_CHECK(vkEndCommandBuffer(cmd));
}

// The jaw/neck bone: pitches the lower scalp around the cranium's centre, +-0.25 rad at 1 Hz.
glm::mat4 jawBone(const glm::vec3& pivot, double t) {
  const float angle = 0.25f * float(std::sin(2.0 * 3.14159265358979 * t));
  return glm::translate(glm::mat4(1.0f), pivot) * glm::rotate(glm::mat4(1.0f), angle, {1, 0, 0}) *
         glm::translate(glm::mat4(1.0f), -pivot);
}

// Skinning data as an application's exporter would give it: roots below the cranium's centre follow the
// jaw bone (1), those well above the cranium (0), blended in between.
hp::ScalpInput jawSkin(const hp::HairAsset& asset, const glm::vec3& pivot) {
  hp::ScalpInput scalp;
  scalp.kind = hp::ScalpInput::Kind::Bones;
  scalp.boneCount = 2;
  for (std::uint32_t g = 0; g < asset.guides.guideCount(); ++g) {
    const float w = std::clamp((pivot.y + 0.04f - asset.guides.guide(g)[0].y) / 0.04f, 0.0f, 1.0f);
    scalp.skin.push_back({glm::uvec4(0, 1, 0, 0), glm::vec4(1.0f - w, w, 0.0f, 0.0f)});
  }
  return scalp;
}

int run(bool validation, std::uint32_t frames, const std::string& out) {
  App app;
  try {
    app.create(validation);
    {
      auto ctx = hp::vk::Context::adopt({vkGetInstanceProcAddr, app.instance, app.physical, app.device, app.family,
                                         app.queue, true});
      hp::RendererSettings rs;
      rs.formats = {kColor, kDepth, VK_SAMPLE_COUNT_1_BIT};
      rs.framesInFlight = kFramesInFlight;
      hp::Renderer renderer(*ctx, rs);
      const hp::HairAsset skinnedAsset =
          hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), {hp::DensityOptions::Mode::Total, 8, 4000, 7});
      const hp::HairAsset rigidAsset =
          hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), {hp::DensityOptions::Mode::Total, 8, 2500, 11});
      const glm::vec3 pivot = hp::kCraniumCenter;  // the jaw bone turns about the cranium's center
      hp::InstanceSettings skinned;
      skinned.scalp = jawSkin(skinnedAsset, pivot);
      hp::InstanceSettings rigid;
      rigid.material.absorption = hp::absorptionFromColor({0.85, 0.7, 0.45});  // blonde
      const glm::mat4 rigidPlace = glm::translate(glm::mat4(1.0f), {0.32f, 0.0f, -0.1f});
      auto jaw = renderer.createInstance(skinnedAsset, skinned);
      auto other = renderer.createInstance(rigidAsset, rigid, rigidPlace);
      hp::HairInstance* heads[] = {jaw.get(), other.get()};
      hp::vk::Image color(*ctx, {kWidth, kHeight, 1, kColor,
                                 VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                 VK_SAMPLE_COUNT_1_BIT, "app colour"});
      hp::vk::Image depth(*ctx, {kWidth, kHeight, 1, kDepth, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                 VK_SAMPLE_COUNT_1_BIT, "app depth"});
      hp::Scene scene;
      scene.camera.target.x = 0.16f;
      scene.camera.distance = 1.2f;
      const hp::View view{hp::orbitCamera(scene.camera, float(kWidth) / kHeight), {kWidth, kHeight}, false, 0};
      for (std::uint32_t f = 0; f < frames; ++f) {
        const std::uint32_t slot = f % kFramesInFlight;
        app.waitSlot(slot);  // frame f - kFramesInFlight is done
        const double t0 = f / 60.0, t1 = (f + 1) / 60.0;
        const glm::mat4 bones[] = {glm::mat4(1.0f), jawBone(pivot, t1)};
        jaw->setBones(bones);
        other->setMotion({rigidPlace * hp::headTransformAt(hp::HeadAnimation::Nod, t0, 0.1f),
                          rigidPlace * hp::headTransformAt(hp::HeadAnimation::Nod, t1, 0.1f), t0, false});
        recordFrame(app.cmds[slot], renderer, f, heads, scene.light, view, color, depth);
        app.submit(slot);
      }
      for (std::uint32_t slot = 0; slot < kFramesInFlight; ++slot) app.waitSlot(slot);
      auto bytes = hp::vk::readbackImage(*ctx, color, hp::vk::ImageUse::ColorAttachment);
      std::vector<std::uint8_t> rgba(bytes.size());
      std::memcpy(rgba.data(), bytes.data(), bytes.size());
      hp::writePng(out, kWidth, kHeight, 4, rgba);
    }  // hairpipe is destroyed here, before the application's device
    app.destroy();
  } catch (const std::exception& e) {
    std::cerr << "embed_minimal: error: " << e.what() << "\n";
    app.destroy();
    return 1;
  }
  if (validationMessages > 0) {
    std::cerr << "embed_minimal: " << validationMessages << " validation message(s)\n";
    return 1;
  }
  std::cout << "embed_minimal: rendered " << frames << " frames of two heads (" << kFramesInFlight
            << " in flight) into the application's attachments; wrote " << out << "\n";
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  bool validation = false;
  std::uint32_t frames = 30;
  std::string out = "embed_minimal.png";
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--validation") validation = true;
    else if (a == "--frames" && i + 1 < argc) frames = static_cast<std::uint32_t>(std::stoul(argv[++i]));
    else if (a == "--out" && i + 1 < argc) out = argv[++i];
    else {
      std::cerr << "usage: hairpipe_embed_minimal [--validation] [--frames N] [--out FILE.png]\n";
      return 1;
    }
  }
  return run(validation, frames, out);
}
