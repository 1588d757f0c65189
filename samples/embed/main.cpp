// The embedding sample: an application that owns its Vulkan instance, device, queue, attachments and
// command buffers, built against the installed package (find_package(hairpipe), <hairpipe/hairpipe.h>).
// It calls Vulkan through the loader (libvulkan) as many engines do; hairpipe loads its own functions
// from the vkGetInstanceProcAddr it is handed. The application:
//   1. creates its Vulkan 1.3 device (dynamicRendering + synchronization2, a graphics+compute queue),
//   2. hands the handles to hairpipe::Context::adopt and creates one hairpipe::Renderer for its formats,
//   3. creates two hair instances: one whose lower scalp is skinned to a jaw/neck bone, one rigid head,
//   4. each frame records hairpipe's update, shadows and draw into ITS command buffer and ITS rendering,
//      with two frames in flight (a command buffer and fence per slot); with --raster compute the hair
//      is drawn by the compute rasterizer between two renderings, with the barriers the contract in
//      <hairpipe/renderer.h> lists, written here in plain Vulkan; a second camera (a close-up, its own
//      attachments, and with the compute raster its own hairpipe::RasterTarget) reuses the frame's update and
//      shadows, and its picture is copied into the main image's corner,
//   5. draws its own wall behind the heads in the hair's shadow (backdrop.h: its shader includes
//      <hairpipe/hair_shadows.glsl> and reads the maps Renderer::hairShadows() hands out), and its own flat
//      cap over one head, which shadows that head's hair (hat.h: drawn into the heads' depth map that
//      Renderer::occluderTargets() hands out, RendererSettings::applicationOccluders),
//   6. reads its colour attachment back, writes a PNG (libpng, its own), destroys hairpipe before its device.
// Every hairpipe call returns a Status or Result (no exceptions cross the boundary).
// Usage: hairpipe_embed [--validation] [--frames N] [--raster graphics|compute] [--out FILE.png] [--fail-at-frame N]
// With --validation, VK_LAYER_KHRONOS_validation runs with synchronization validation; any message fails.
// --fail-at-frame N: the application fails after submitting frame N (frames still in flight), as an engine's
// error would; it waits for its device before hairpipe's objects go, and exits with 1 and no PNG.
#include <png.h>
#include <vulkan/vulkan.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>  // the application's own math library

#include <hairpipe/hairpipe.h>

#include "backdrop.h"
#include "hat.h"
#include "pipeline.h"

namespace {
constexpr std::uint32_t kWidth = 160, kHeight = 120;
// A second camera's picture (a close-up of the capped head), set into the main image's top left corner, over
// the wall.
constexpr std::uint32_t kInsetWidth = 64, kInsetHeight = 48;
constexpr VkFormat kColor = VK_FORMAT_R8G8B8A8_UNORM;  // the app's own choice of formats
// Depth with stencil, as a game's main pass has it (pickDepthFormat: the first the device supports), attached
// as both depth and stencil; the compute rasterizer samples its depth aspect.
constexpr VkFormat kDepthCandidates[] = {VK_FORMAT_D32_SFLOAT_S8_UINT, VK_FORMAT_D24_UNORM_S8_UINT};
constexpr VkImageAspectFlags kDepthAspects = VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
constexpr std::uint32_t kFramesInFlight = 2;

// hairpipe reports failures as values; this application turns them into its own exceptions.
void check(const hairpipe::Status& status) {
  if (!status) throw std::runtime_error(status.message());
}
template <class T>
T take(hairpipe::Result<T> result) {
  if (!result) throw std::runtime_error(result.message());
  return std::move(result).value();
}
hairpipe::Mat4 toHairpipe(const glm::mat4& m) {
  hairpipe::Mat4 out;
  std::memcpy(out.m, &m, sizeof(out.m));  // both column-major
  return out;
}

std::uint32_t validationMessages = 0;
VKAPI_ATTR VkBool32 VKAPI_CALL onMessage(VkDebugUtilsMessageSeverityFlagBitsEXT, VkDebugUtilsMessageTypeFlagsEXT,
                                         const VkDebugUtilsMessengerCallbackDataEXT* data, void*) {
  std::cerr << "validation: " << data->pMessage << "\n";
  ++validationMessages;
  return VK_FALSE;
}

// Synchronization validation is off by default in the layer; VkValidationFeaturesEXT turns it on.
constexpr VkValidationFeatureEnableEXT kSyncValidation = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;

// An image with its memory and view, created and destroyed by the application.
struct Attachment {
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;
};

// What one camera renders into: colour and depth/stencil attachments, and the depth aspect's own view for the
// compute rasterizer.
struct ViewTargets {
  VkExtent2D extent{};
  Attachment color, depth;
  VkImageView depthSampled = VK_NULL_HANDLE;
};

// Everything the application owns, created and destroyed by the application with plain Vulkan.
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
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;
  ViewTargets main, inset;  // the main camera's and the second camera's
  std::uint32_t failAtFrame = UINT32_MAX;  // --fail-at-frame: the application fails there (its unwinding, tested)

  void failIfAsked(std::uint32_t frame) const {
    if (frame == failAtFrame) throw std::runtime_error("the application failed at frame " + std::to_string(frame));
  }

  void createInstance(bool validation) {
    VkApplicationInfo appInfo{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    appInfo.pApplicationName = "hairpipe_embed";
    appInfo.apiVersion = VK_API_VERSION_1_3;
    const char* layer = "VK_LAYER_KHRONOS_validation";
    const char* ext = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = &kSyncValidation;
    VkInstanceCreateInfo ii{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, validation ? &features : nullptr};
    ii.pApplicationInfo = &appInfo;
    ii.enabledLayerCount = validation ? 1 : 0;
    ii.ppEnabledLayerNames = &layer;
    ii.enabledExtensionCount = 1;
    ii.ppEnabledExtensionNames = &ext;
    check(vkCreateInstance(&ii, nullptr, &instance), "vkCreateInstance");
    if (validation) {
      auto createMessenger = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT"));
      VkDebugUtilsMessengerCreateInfoEXT mi{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
      mi.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
      mi.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT;
      mi.pfnUserCallback = onMessage;
      check(createMessenger(instance, &mi, nullptr, &messenger), "vkCreateDebugUtilsMessengerEXT");
    }
  }

  void pickDevice() {
    std::uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    check(vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices");
    for (VkPhysicalDevice d : devices)  // the first device hairpipe can run on
      if (const auto reasons = hairpipe::unfitReasons(vkGetInstanceProcAddr, instance, d); reasons && reasons.value().empty()) {
        physical = d;
        break;
      }
    if (!physical) throw std::runtime_error("no Vulkan device fit for hairpipe");
    std::uint32_t families = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, nullptr);
    std::vector<VkQueueFamilyProperties> props(families);
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &families, props.data());
    constexpr VkQueueFlags kNeeded = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    while (family < families && (props[family].queueFlags & kNeeded) != kNeeded) ++family;
    if (family == families) throw std::runtime_error("no graphics+compute queue");
    pickDepthFormat();
  }

  void pickDepthFormat() {
    constexpr VkFormatFeatureFlags kNeeded = VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT;
    for (VkFormat f : kDepthCandidates) {
      VkFormatProperties props{};
      vkGetPhysicalDeviceFormatProperties(physical, f, &props);
      if ((props.optimalTilingFeatures & kNeeded) == kNeeded) {
        depthFormat = f;
        return;
      }
    }
    throw std::runtime_error("no sampled depth/stencil format");
  }

  void createDevice() {
    float priority = 1.0f;
    VkDeviceQueueCreateInfo qi{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qi.queueFamilyIndex = family;
    qi.queueCount = 1;
    qi.pQueuePriorities = &priority;
    VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    v13.dynamicRendering = VK_TRUE;  // what hairpipe::requirements() lists
    v13.synchronization2 = VK_TRUE;
    VkDeviceCreateInfo di{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &v13};
    di.queueCreateInfoCount = 1;
    di.pQueueCreateInfos = &qi;
    check(vkCreateDevice(physical, &di, nullptr, &device), "vkCreateDevice");
    vkGetDeviceQueue(device, family, 0, &queue);
    VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pi.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pi.queueFamilyIndex = family;
    check(vkCreateCommandPool(device, &pi, nullptr, &pool), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = pool;
    ai.commandBufferCount = kFramesInFlight;
    check(vkAllocateCommandBuffers(device, &ai, cmds), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fi{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    for (VkFence& f : fences) check(vkCreateFence(device, &fi, nullptr, &f), "vkCreateFence");
  }

  std::uint32_t memoryType(std::uint32_t bits, VkMemoryPropertyFlags flags) const {
    VkPhysicalDeviceMemoryProperties props;
    vkGetPhysicalDeviceMemoryProperties(physical, &props);
    for (std::uint32_t i = 0; i < props.memoryTypeCount; ++i)
      if ((bits & (1u << i)) && (props.memoryTypes[i].propertyFlags & flags) == flags) return i;
    throw std::runtime_error("no suitable memory type");
  }

  VkDeviceMemory allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags flags) const {
    VkMemoryAllocateInfo mi{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    mi.allocationSize = req.size;
    mi.memoryTypeIndex = memoryType(req.memoryTypeBits, flags);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    check(vkAllocateMemory(device, &mi, nullptr, &memory), "vkAllocateMemory");
    return memory;
  }

  VkImageView createView(VkImage image, VkFormat format, VkImageAspectFlags aspect) const {
    VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vi.image = image;
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = format;
    vi.subresourceRange = {aspect, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    check(vkCreateImageView(device, &vi, nullptr, &view), "vkCreateImageView");
    return view;
  }

  Attachment createAttachment(VkExtent2D extent, VkFormat format, VkImageUsageFlags usage, VkImageAspectFlags aspect) const {
    Attachment a;
    VkImageCreateInfo ii{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ii.imageType = VK_IMAGE_TYPE_2D;
    ii.format = format;
    ii.extent = {extent.width, extent.height, 1};
    ii.mipLevels = ii.arrayLayers = 1;
    ii.samples = VK_SAMPLE_COUNT_1_BIT;
    ii.usage = usage;
    check(vkCreateImage(device, &ii, nullptr, &a.image), "vkCreateImage");
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device, a.image, &req);
    a.memory = allocate(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    check(vkBindImageMemory(device, a.image, a.memory, 0), "vkBindImageMemory");
    a.view = createView(a.image, format, aspect);
    return a;
  }

  ViewTargets createViewTargets(VkExtent2D extent) const {
    ViewTargets t;
    t.extent = extent;
    t.color = createAttachment(extent, kColor, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                                   VK_IMAGE_USAGE_TRANSFER_DST_BIT, VK_IMAGE_ASPECT_COLOR_BIT);
    // SAMPLED: the compute rasterizer reads the depth (renderer.h lists each image's usage).
    t.depth = createAttachment(extent, depthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                               kDepthAspects);
    t.depthSampled = createView(t.depth.image, depthFormat, VK_IMAGE_ASPECT_DEPTH_BIT);
    return t;
  }

  void destroyViewTargets(ViewTargets& t) const {
    destroyAttachment(t.color);
    if (t.depthSampled) vkDestroyImageView(device, t.depthSampled, nullptr);
    destroyAttachment(t.depth);
    t = {};
  }

  void destroyAttachment(Attachment& a) const {
    if (a.view) vkDestroyImageView(device, a.view, nullptr);
    if (a.image) vkDestroyImage(device, a.image, nullptr);
    if (a.memory) vkFreeMemory(device, a.memory, nullptr);
    a = {};
  }

  // The slot's previous frame (frame - kFramesInFlight) is done: its command buffer is free again.
  void waitSlot(std::uint32_t slot) {
    if (!pending[slot]) return;
    check(vkWaitForFences(device, 1, &fences[slot], VK_TRUE, UINT64_MAX), "vkWaitForFences");
    check(vkResetFences(device, 1, &fences[slot]), "vkResetFences");
    pending[slot] = false;
  }

  void submit(std::uint32_t slot) {
    VkCommandBufferSubmitInfo ci{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
    ci.commandBuffer = cmds[slot];
    VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
    si.commandBufferInfoCount = 1;
    si.pCommandBufferInfos = &ci;
    check(vkQueueSubmit2(queue, 1, &si, fences[slot]), "vkQueueSubmit2");
    pending[slot] = true;
  }

  void destroy() {
    if (device) vkDeviceWaitIdle(device);
    if (device) destroyViewTargets(main);
    if (device) destroyViewTargets(inset);
    for (VkFence f : fences)
      if (f) vkDestroyFence(device, f, nullptr);
    if (pool) vkDestroyCommandPool(device, pool, nullptr);
    if (device) vkDestroyDevice(device, nullptr);
    if (messenger)
      reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
          vkGetInstanceProcAddr(instance, "vkDestroyDebugUtilsMessengerEXT"))(instance, messenger, nullptr);
    if (instance) vkDestroyInstance(instance, nullptr);
    *this = {};
  }
};

// Both frames in flight render into the same attachments: each frame discards them (layout UNDEFINED)
// after the previous frame's attachment writes (and, for colour, the inset's or the readback's copy) are done.
void beginAttachments(VkCommandBuffer cmd, const ViewTargets& targets) {
  constexpr VkPipelineStageFlags2 kDepthStages =
      VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  transition(cmd, targets.color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
             VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
             VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_2_COPY_BIT,
             VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
             VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
  transition(cmd, targets.depth.image, kDepthAspects, VK_IMAGE_LAYOUT_UNDEFINED,
             VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, kDepthStages, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
             kDepthStages,
             VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
}

VkRenderingAttachmentInfo attachmentInfo(VkImageView view, VkImageLayout layout, VkAttachmentStoreOp store,
                                         VkClearValue clear) {
  VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  a.imageView = view;
  a.imageLayout = layout;
  a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  a.storeOp = store;
  a.clearValue = clear;
  return a;
}

// [embed-readme-begin]
// The application's own geometry: a wall that receives the hair's shadow, a flat cap that casts one.
struct Scenery {
  const Backdrop& backdrop;
  const Hat& hat;
  glm::mat4 hatPlace;  // this frame's: the hat sits on the second head
};

// One camera of the frame and where it renders: the main view with the Renderer's own raster target, the
// inset with one the application made (hairpipe::RasterTarget) for its own extent and depth image.
struct Camera {
  const ViewTargets& targets;
  hairpipe::View view;
  hairpipe::RasterTarget* raster = nullptr;  // compute raster: null for the Renderer's own target
};

// The application's own rendering of one camera (its colour, depth and stencil attachments) with hairpipe's
// draw inside it. With the compute rasterizer, the hair is drawn between that rendering and a second one of
// the same attachments.
void recordCamera(VkCommandBuffer cmd, hairpipe::Renderer& renderer, const Scenery& scenery, std::uint64_t frame,
                  std::span<hairpipe::Instance* const> heads, std::span<const hairpipe::Light> lights,
                  const Camera& camera) {
  const bool compute = renderer.raster() == hairpipe::RasterMode::Compute;
  const ViewTargets& targets = camera.targets;
  const hairpipe::View& view = camera.view;
  beginAttachments(cmd, targets);
  VkRenderingAttachmentInfo color = attachmentInfo(targets.color.view, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
                                                   VK_ATTACHMENT_STORE_OP_STORE, {{{0.2f, 0.25f, 0.3f, 1.0f}}});
  VkClearValue far{};
  far.depthStencil = {1.0f, 0};
  VkRenderingAttachmentInfo depth = attachmentInfo(targets.depth.view, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                                                   compute ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE, far);
  VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
  ri.renderArea = {{0, 0}, targets.extent};
  ri.layerCount = 1;
  ri.colorAttachmentCount = 1;
  ri.pColorAttachments = &color;
  ri.pDepthAttachment = &depth;
  ri.pStencilAttachment = &depth;  // one combined image: RendererSettings::formats.stencil says so
  vkCmdBeginRendering(cmd, &ri);
  // Your opaque geometry first (the graphics raster blends the hair over what is drawn before it): a wall in
  // the hair's shadow, read from the maps recordShadows just wrote, and the hat.
  scenery.backdrop.record(cmd, view, lights[0], take(renderer.hairShadows()), take(heads[0]->hairShadowForward()));
  scenery.hat.record(cmd, view, scenery.hatPlace);
  check(renderer.recordDraw(cmd, frame, view, heads));      // heads (+ hair ribbons in graphics mode)
  vkCmdEndRendering(cmd);
  if (compute) {
    constexpr VkPipelineStageFlags2 kDepthStages =
        VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
    transition(cmd, targets.depth.image, kDepthAspects, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
               VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, kDepthStages, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    // The hair of every head, against the depth: into the Renderer's own target or the camera's.
    check(camera.raster ? renderer.recordRaster(cmd, frame, view, *camera.raster) : renderer.recordRaster(cmd, frame, view));
    transition(cmd, targets.depth.image, kDepthAspects, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
               VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_NONE,
               kDepthStages, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    transition(cmd, targets.color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
               VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
               VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
               VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    color.loadOp = depth.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    vkCmdBeginRendering(cmd, &ri);
    check(camera.raster ? renderer.recordComposite(cmd, targets.extent, *camera.raster)  // the hair over the colour
                        : renderer.recordComposite(cmd, targets.extent));
    vkCmdEndRendering(cmd);
  }
}

// The inset camera's colour copied into the main image's top left corner, which is left as the main
// rendering left it (COLOR_ATTACHMENT_OPTIMAL, its writes visible to colour output).
void copyInset(VkCommandBuffer cmd, const App& app) {
  transition(cmd, app.inset.color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
             VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
             VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
  transition(cmd, app.main.color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
             VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
             VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  VkImageCopy region{};
  region.srcSubresource = region.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.dstOffset = {4, 4, 0};
  region.extent = {kInsetWidth, kInsetHeight, 1};
  vkCmdCopyImage(cmd, app.inset.color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, app.main.color.image,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
  transition(cmd, app.main.color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
             VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
             VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
}

// One frame of the application: hairpipe's update and shadows outside rendering, once for the frame; then
// each camera's rendering, both reusing them; then the inset into the main image.
void recordFrame(VkCommandBuffer cmd, const App& app, hairpipe::Renderer& renderer, const Scenery& scenery,
                 std::uint64_t frame, std::span<hairpipe::Instance* const> heads,
                 std::span<const hairpipe::Light> lights, std::span<const Camera> cameras) {
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &bi), "vkBeginCommandBuffer");
  check(renderer.recordUpdate(cmd, frame, heads));          // simulate, tessellate, interpolate
  check(renderer.recordShadows(cmd, frame, lights, heads));  // per shadowed light, one map set over all heads
  scenery.hat.recordShadow(cmd, take(renderer.occluderTargets()), scenery.hatPlace);  // your casters, after it
  for (const Camera& camera : cameras) recordCamera(cmd, renderer, scenery, frame, heads, lights, camera);
  copyInset(cmd, app);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
}

// The jaw/neck bone: pitches the lower scalp around the cranium's centre, +-0.25 rad at 1 Hz.
glm::mat4 jawBone(const glm::vec3& pivot, double t) {
  const float angle = 0.25f * float(std::sin(2.0 * 3.14159265358979 * t));
  return glm::translate(glm::mat4(1.0f), pivot) * glm::rotate(glm::mat4(1.0f), angle, {1, 0, 0}) *
         glm::translate(glm::mat4(1.0f), -pivot);
}

// Skinning data as an application's exporter would give it: roots below the cranium's centre follow the
// jaw bone (1), those well above it the skull (0), blended in between; up to 4 bones per guide root.
hairpipe::ScalpInput jawSkin(const hairpipe::Asset& asset, const glm::vec3& pivot) {
  hairpipe::ScalpInput scalp;
  scalp.kind = hairpipe::ScalpInput::Kind::Bones;  // or RootFrames (your skinning's buffer), or Rigid
  scalp.boneCount = 2;
  for (const hairpipe::Vec3& root : take(asset.guideRoots())) {
    const float w = std::clamp((pivot.y + 0.04f - root.y) / 0.04f, 0.0f, 1.0f);
    scalp.skin.push_back({{0, 1, 0, 0}, {1.0f - w, w, 0.0f, 0.0f}});
  }
  return scalp;
}

// A nodding head: +-0.1 rad about the x axis at 1 Hz.
glm::mat4 nod(double t) { return glm::rotate(glm::mat4(1.0f), 0.1f * float(std::sin(6.2831853 * t)), {1, 0, 0}); }

void renderFrames(App& app, std::uint32_t frames, hairpipe::RasterMode raster) {
  // Your device: Vulkan 1.3, dynamicRendering + synchronization2 enabled, compute subgroups, a graphics+compute queue.
  hairpipe::Context ctx = take(hairpipe::Context::adopt(
      {vkGetInstanceProcAddr, app.instance, app.physical, app.device, app.family, app.queue, true}));
  hairpipe::RendererSettings rs;
  rs.formats = {kColor, app.depthFormat, VK_SAMPLE_COUNT_1_BIT, app.depthFormat};  // your attachments
  rs.framesInFlight = kFramesInFlight;
  rs.raster = raster;
  rs.shadowedLights = 2;  // the key and the rim cast hair shadows
  rs.applicationOccluders = true;  // the cap shadows the hair too
  rs.growRasterLists = true;       // compute raster: tile lists sized by the frames' need, not a close-up's
  hairpipe::Renderer renderer = take(hairpipe::Renderer::create(ctx, rs));

  // One asset (guides, head mesh, interpolation topology), two heads with their own state and material.
  const hairpipe::Asset asset = take(hairpipe::defaultHeadAsset({hairpipe::Density::Mode::Total, 8, 2000, 7}));
  const glm::vec3 pivot{0.0f, 0.005f, -0.012f};  // the jaw bone turns about the cranium's centre
  hairpipe::InstanceSettings skinned;            // material, simulation, look, scalp input
  skinned.scalp = jawSkin(asset, pivot);
  hairpipe::InstanceSettings rigid;
  rigid.material.absorption = take(hairpipe::absorptionFromColor(0.85f, 0.7f, 0.45f));  // blonde
  const glm::mat4 rigidPlace = glm::translate(glm::mat4(1.0f), {0.32f, 0.0f, -0.1f});
  hairpipe::Instance jaw = take(renderer.createInstance(asset, skinned));
  hairpipe::Instance other = take(renderer.createInstance(asset, rigid, toHairpipe(rigidPlace)));
  hairpipe::Instance* heads[] = {&jaw, &other};
  const Backdrop backdrop(app.device, take(renderer.hairShadows()), rs.formats);  // your geometry, in the hair's shadow
  const Hat hat(app.device, VK_FORMAT_D32_SFLOAT, rs.formats);  // and casting one
  // The compute raster draws each camera into a target of its extent and depth: the Renderer's own for the
  // main camera, one of the application's for the inset (an engine's second eye, split screen or mirror).
  std::optional<hairpipe::RasterTarget> insetRaster;
  if (raster == hairpipe::RasterMode::Compute) {
    check(renderer.setRasterTarget(app.main.extent, app.main.depthSampled, heads));
    insetRaster.emplace(take(renderer.createRasterTarget(app.inset.extent, app.inset.depthSampled, heads)));
  }
  const Camera cameras[] = {
      {app.main, take(hairpipe::makeView({{0.751f, 0.128f, 1.023f}, {0.16f, -0.08f, 0.0f}, {0.0f, 1.0f, 0.0f}, 0.6109f,
                                          0.024f, 24.0f}, app.main.extent))},
      {app.inset,  // a close-up of the capped head; View::index 1: the second view of each frame
       take(hairpipe::makeView({{0.56f, 0.06f, 0.42f}, {0.32f, 0.0f, -0.1f}, {0.0f, 1.0f, 0.0f}, 0.6109f, 0.024f, 24.0f},
                               app.inset.extent, 1)),
       insetRaster ? &*insetRaster : nullptr}};
  // Your lights: a key and a cool rim from behind, both shadowed, and a warm point fill.
  hairpipe::Light rim;
  rim.direction = {-0.3939193f, 0.3939193f, -0.8304548f};
  rim.color = {0.7f, 0.8f, 1.0f};
  rim.intensity = 2.0f;
  hairpipe::Light fill;
  fill.type = hairpipe::Light::Type::Point;
  fill.position = {-0.5f, 0.0f, 0.6f};
  fill.range = 0.8f;
  fill.color = {1.0f, 0.85f, 0.7f};
  fill.intensity = 0.6f;
  fill.shadows = false;
  hairpipe::Light key;  // from the upper left, so the hair's shadows fall on the wall beside the heads
  key.direction = {-0.5496154f, 0.4996504f, 0.6695315f};
  const hairpipe::Light lights[] = {key, rim, fill};
  try {
    for (std::uint32_t f = 0; f < frames; ++f) {
      const std::uint32_t slot = f % kFramesInFlight;
      app.waitSlot(slot);  // frame f - kFramesInFlight is done: its slot and command buffer are free
      const double t0 = f / 60.0, t1 = (f + 1) / 60.0;
      const hairpipe::Mat4 bones[] = {toHairpipe(glm::mat4(1.0f)), toHairpipe(jawBone(pivot, t1))};
      check(jaw.setBones(bones));  // per-frame inputs: bones, colliders, motion
      check(other.setMotion({toHairpipe(rigidPlace * nod(t0)), toHairpipe(rigidPlace * nod(t1)), t0, false}));
      recordFrame(app.cmds[slot], app, renderer, {backdrop, hat, rigidPlace * nod(t1)}, f, heads, lights, cameras);
      app.submit(slot);
      app.failIfAsked(f);  // with frames in flight
    }
    for (std::uint32_t slot = 0; slot < kFramesInFlight; ++slot) app.waitSlot(slot);
  } catch (...) {
    // hairpipe's objects go while this unwinds: the frames in flight that use them must be done first
    // (a lost device needs no wait; its error is the one rethrown).
    if (vkDeviceWaitIdle(app.device) != VK_SUCCESS) std::cerr << "hairpipe_embed: vkDeviceWaitIdle failed while unwinding\n";
    throw;
  }
}  // hairpipe (the inset's raster target, instances, renderer, context) is destroyed here, before the device
// [embed-readme-end]

// Copies the colour attachment into a host-visible buffer and returns its RGBA8 texels.
std::vector<std::uint8_t> readColor(App& app) {
  const VkDeviceSize bytes = VkDeviceSize(kWidth) * kHeight * 4;
  VkBufferCreateInfo bi{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  bi.size = bytes;
  bi.usage = VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  check(vkCreateBuffer(app.device, &bi, nullptr, &buffer), "vkCreateBuffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(app.device, buffer, &req);
  VkDeviceMemory memory =
      app.allocate(req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
  check(vkBindBufferMemory(app.device, buffer, memory, 0), "vkBindBufferMemory");
  VkCommandBuffer cmd = app.cmds[0];
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &begin), "vkBeginCommandBuffer");
  transition(cmd, app.main.color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
             VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
             VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {kWidth, kHeight, 1};
  vkCmdCopyImageToBuffer(cmd, app.main.color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  app.submit(0);
  app.waitSlot(0);
  void* mapped = nullptr;
  check(vkMapMemory(app.device, memory, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
  std::vector<std::uint8_t> rgba(bytes);
  std::memcpy(rgba.data(), mapped, bytes);
  vkUnmapMemory(app.device, memory);
  vkDestroyBuffer(app.device, buffer, nullptr);
  vkFreeMemory(app.device, memory, nullptr);
  return rgba;
}

// Writes RGBA8 rows as a PNG with libpng; a failed write removes the file.
void writePng(const std::string& path, const std::vector<std::uint8_t>& rgba) {
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) throw std::runtime_error("cannot open " + path);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
    std::remove(path.c_str());
    throw std::runtime_error("writing " + path + " failed");
  }
  png_init_io(png, file);
  png_set_IHDR(png, info, kWidth, kHeight, 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (std::uint32_t y = 0; y < kHeight; ++y) png_write_row(png, rgba.data() + std::size_t(y) * kWidth * 4);
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  if (std::fclose(file) != 0) throw std::runtime_error("writing " + path + " failed");
}

int run(bool validation, std::uint32_t frames, hairpipe::RasterMode raster, const std::string& out,
        std::uint32_t failAtFrame) {
  App app;
  app.failAtFrame = failAtFrame;
  try {
    app.createInstance(validation);
    app.pickDevice();
    app.createDevice();
    app.main = app.createViewTargets({kWidth, kHeight});
    app.inset = app.createViewTargets({kInsetWidth, kInsetHeight});
    renderFrames(app, frames, raster);
    writePng(out, readColor(app));
    app.destroy();
  } catch (const std::exception& e) {  // hairpipe's failures (as the application raised them) and its own
    std::cerr << "hairpipe_embed: error: " << e.what() << "\n";
    app.destroy();
    return 1;
  }
  if (validationMessages > 0) {
    std::cerr << "hairpipe_embed: " << validationMessages << " validation message(s)\n";
    return 1;
  }
  std::cout << "hairpipe_embed: rendered " << frames << " frames of two heads (" << kFramesInFlight
            << " in flight) from two cameras into the application's attachments; wrote " << out << "\n";
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  bool validation = false;
  std::uint32_t frames = 30;
  std::string out = "embed.png";
  std::uint32_t failAtFrame = UINT32_MAX;
  hairpipe::RasterMode raster = hairpipe::RasterMode::Graphics;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--validation") validation = true;
    else if (a == "--frames" && i + 1 < argc) frames = static_cast<std::uint32_t>(std::stoul(argv[++i]));
    else if (a == "--out" && i + 1 < argc) out = argv[++i];
    else if (a == "--fail-at-frame" && i + 1 < argc) failAtFrame = static_cast<std::uint32_t>(std::stoul(argv[++i]));
    else if (a == "--raster" && i + 1 < argc && std::string(argv[i + 1]) == "graphics") ++i;
    else if (a == "--raster" && i + 1 < argc && std::string(argv[i + 1]) == "compute") {
      raster = hairpipe::RasterMode::Compute;
      ++i;
    } else {
      std::cerr << "usage: hairpipe_embed [--validation] [--frames N] [--raster graphics|compute] [--out FILE.png]"
                   " [--fail-at-frame N]\n";
      return 1;
    }
  }
  return run(validation, frames, raster, out, failAtFrame);
}
