// A minimal embedding of hairpipe in an application that owns its Vulkan instance, device, queue,
// attachments and command buffers (ARCHITECTURE.md "Embedding contract"). The application:
//   1. creates its Vulkan 1.3 device with dynamicRendering + synchronization2 and a graphics+compute queue,
//   2. hands the handles to hp::vk::Context::adopt,
//   3. each frame records hairpipe's update and draw into ITS command buffer and ITS rendering,
//   4. waits on ITS fence before reusing the command buffer, and destroys hairpipe before its device.
// Usage: hairpipe_embed_minimal [--validation] [--frames N] [--out FILE.png]
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "engine/error.h"
#include "engine/hair/default_head.h"
#include "engine/hair_system.h"
#include "tools/png_file.h"
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
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;

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
    ai.commandBufferCount = 1;
    HP_VK_CHECK(vkAllocateCommandBuffers(device, &ai, &cmd));
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    HP_VK_CHECK(vkCreateFence(device, &fi, nullptr, &fence));
  }

  void submitAndWait() {
    VkCommandBufferSubmitInfo ci{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    ci.commandBuffer = cmd;
    VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    si.commandBufferInfoCount = 1;
    si.pCommandBufferInfos = &ci;
    HP_VK_CHECK(vkQueueSubmit2(queue, 1, &si, fence));
    HP_VK_CHECK(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX));
    HP_VK_CHECK(vkResetFences(device, 1, &fence));
  }

  void destroy() {
    if (device) vkDeviceWaitIdle(device);
    if (fence) vkDestroyFence(device, fence, nullptr);
    if (pool) vkDestroyCommandPool(device, pool, nullptr);
    if (device) vkDestroyDevice(device, nullptr);
    if (messenger) vkDestroyDebugUtilsMessengerEXT(instance, messenger, nullptr);
    if (instance) vkDestroyInstance(instance, nullptr);
  }
};

// One frame of the application: hairpipe's compute and prepare steps, then the app's own rendering
// with hairpipe's draw inside it.
void recordFrame(App& app, hp::HairSystem& hair, const hp::HeadMotion& motion, const hp::DrawView& view,
                 const hp::vk::Image& color, const hp::vk::Image& depth) {
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  HP_VK_CHECK(vkBeginCommandBuffer(app.cmd, &bi));
  hair.recordUpdate(app.cmd, motion);
  hair.recordPrepareDraw(app.cmd, view);
  hp::vk::imageBarrier(app.cmd, color.handle(), VK_IMAGE_ASPECT_COLOR_BIT, hp::vk::ImageUse::Undefined,
                       hp::vk::ImageUse::ColorAttachment);
  hp::vk::imageBarrier(app.cmd, depth.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, hp::vk::ImageUse::Undefined,
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
  vkCmdBeginRendering(app.cmd, &ri);
  hair.recordDraw(app.cmd, view);
  vkCmdEndRendering(app.cmd);
  HP_VK_CHECK(vkEndCommandBuffer(app.cmd));
}

int run(bool validation, std::uint32_t frames, const std::string& out) {
  App app;
  try {
    app.create(validation);
    {
      auto ctx = hp::vk::Context::adopt({vkGetInstanceProcAddr, app.instance, app.physical, app.device, app.family,
                                         app.queue, true});
      const hp::HairAsset asset = hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), {hp::DensityOptions::Mode::Total, 8, 4000, 7});
      hp::HairSystemSettings settings;
      settings.formats = {kColor, kDepth, VK_SAMPLE_COUNT_1_BIT};
      hp::HairSystem hair(*ctx, asset, settings);
      hp::vk::Image color(*ctx, {kWidth, kHeight, 1, kColor,
                                 VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                 VK_SAMPLE_COUNT_1_BIT, "app colour"});
      hp::vk::Image depth(*ctx, {kWidth, kHeight, 1, kDepth, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                 VK_SAMPLE_COUNT_1_BIT, "app depth"});
      hp::Scene scene;
      hp::DrawView view;
      view.extent = {kWidth, kHeight};
      view.camera = hp::orbitCamera(scene.camera, float(kWidth) / kHeight);
      view.light = scene.light;
      for (std::uint32_t f = 0; f < frames; ++f) {
        const double t0 = f / 60.0, t1 = (f + 1) / 60.0;
        const hp::HeadMotion motion{hp::headTransformAt(hp::HeadAnimation::Nod, t0, 0.1f),
                                    hp::headTransformAt(hp::HeadAnimation::Nod, t1, 0.1f), t0, false};
        view.headToWorld = motion.to;
        recordFrame(app, hair, motion, view, color, depth);
        app.submitAndWait();  // the app's fence: the command buffer is free again
      }
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
  std::cout << "embed_minimal: rendered " << frames << " frames into the application's attachments; wrote " << out << "\n";
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
