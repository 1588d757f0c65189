// Hello hair: the smallest complete hairpipe application. It creates its own Vulkan instance and device
// (through the loader), adopts them into hairpipe, draws one frame of the default head into its own
// colour and depth images, and writes the colour to hello_hair.png. Build it against the installed
// package (CMakeLists.txt beside this file). The package test runs it under the validation layer with
// synchronization validation, enabled from the environment (VK_INSTANCE_LAYERS, VK_LAYER_ENABLES).
#include <vulkan/vulkan.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <cstdio>

#include <hairpipe/hairpipe.h>

constexpr std::uint32_t W = 320, H = 240;
#define CHECK(call) do { if ((call) != VK_SUCCESS) { std::fprintf(stderr, "%s failed\n", #call); return 1; } } while (0)
#define TAKE(var, result) auto var##_ = (result); if (!var##_) { std::fprintf(stderr, "%s\n", var##_.message().c_str()); return 1; } auto var = std::move(var##_).value()
#define OK(status) do { hairpipe::Status s_ = (status); if (!s_) { std::fprintf(stderr, "%s\n", s_.message().c_str()); return 1; } } while (0)

struct Image { VkImage image; VkDeviceMemory memory; VkImageView view; };

static std::uint32_t memoryType(VkPhysicalDevice gpu, std::uint32_t bits, VkMemoryPropertyFlags flags) {
  VkPhysicalDeviceMemoryProperties p;
  vkGetPhysicalDeviceMemoryProperties(gpu, &p);
  for (std::uint32_t i = 0; i < p.memoryTypeCount; ++i)
    if ((bits >> i & 1) && (p.memoryTypes[i].propertyFlags & flags) == flags) return i;
  return 0;
}

static VkResult makeImage(VkPhysicalDevice gpu, VkDevice dev, VkFormat format, VkImageUsageFlags usage,
                          VkImageAspectFlags aspect, Image& out) {
  VkImageCreateInfo ii{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO, nullptr, 0, VK_IMAGE_TYPE_2D, format, {W, H, 1}, 1, 1,
                       VK_SAMPLE_COUNT_1_BIT, VK_IMAGE_TILING_OPTIMAL, usage};
  if (VkResult r = vkCreateImage(dev, &ii, nullptr, &out.image)) return r;
  VkMemoryRequirements req;
  vkGetImageMemoryRequirements(dev, out.image, &req);
  VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, nullptr, req.size,
                          memoryType(gpu, req.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT)};
  if (VkResult r = vkAllocateMemory(dev, &ai, nullptr, &out.memory)) return r;
  if (VkResult r = vkBindImageMemory(dev, out.image, out.memory, 0)) return r;
  VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO, nullptr, 0, out.image, VK_IMAGE_VIEW_TYPE_2D, format,
                           {}, {aspect, 0, 1, 0, 1}};
  return vkCreateImageView(dev, &vi, nullptr, &out.view);
}

static void barrier(VkCommandBuffer cmd, VkImage image, VkImageAspectFlags aspect, VkImageLayout from, VkImageLayout to,
                    VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2, nullptr, srcStage, srcAccess, dstStage, dstAccess, from, to,
                          VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, image, {aspect, 0, 1, 0, 1}};
  VkDependencyInfo d{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  d.imageMemoryBarrierCount = 1;
  d.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &d);
}

int main() {
  // 1. The application's instance and device: Vulkan 1.3 with dynamicRendering and synchronization2.
  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO, nullptr, "hello_hair", 1, nullptr, 0, VK_API_VERSION_1_3};
  VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, nullptr, 0, &app};
  VkInstance instance;
  CHECK(vkCreateInstance(&ici, nullptr, &instance));
  std::uint32_t count = 1;
  VkPhysicalDevice gpu;
  if (vkEnumeratePhysicalDevices(instance, &count, &gpu) < 0 || count == 0) return std::fprintf(stderr, "no device\n"), 1;
  // Queue family 0 has graphics and compute on the devices this sample targets; hairpipe checks it.
  float priority = 1.0f;
  VkDeviceQueueCreateInfo qi{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO, nullptr, 0, 0, 1, &priority};
  VkPhysicalDeviceVulkan13Features v13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  v13.dynamicRendering = v13.synchronization2 = VK_TRUE;
  VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &v13, 0, 1, &qi};
  VkDevice dev;
  CHECK(vkCreateDevice(gpu, &dci, nullptr, &dev));
  VkQueue queue;
  vkGetDeviceQueue(dev, 0, 0, &queue);
  Image color{}, depth{};
  CHECK(makeImage(gpu, dev, VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                  VK_IMAGE_ASPECT_COLOR_BIT, color));
  CHECK(makeImage(gpu, dev, VK_FORMAT_D32_SFLOAT, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT, depth));
  {
    // 2. hairpipe on the application's device: a renderer for its formats, one head of hair.
    TAKE(ctx, hairpipe::Context::adopt({vkGetInstanceProcAddr, instance, gpu, dev, 0, queue}));
    hairpipe::RendererSettings settings;
    settings.formats = {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_1_BIT};
    TAKE(renderer, hairpipe::Renderer::create(ctx, settings));
    TAKE(asset, hairpipe::defaultHeadAsset({hairpipe::Density::Mode::Total, 8, 5000, 7}));
    TAKE(head, renderer.createInstance(asset, {}));
    TAKE(view, hairpipe::makeView({{0.5f, 0.1f, 0.75f}, {0.0f, -0.05f, 0.0f}}, {W, H}));
    // 3. One frame into the application's command buffer: update and shadows, then its rendering.
    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO, nullptr, 0, 0};
    VkCommandPool pool;
    CHECK(vkCreateCommandPool(dev, &pci, nullptr, &pool));
    VkCommandBufferAllocateInfo cai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr, pool, VK_COMMAND_BUFFER_LEVEL_PRIMARY, 1};
    VkCommandBuffer cmd;
    CHECK(vkAllocateCommandBuffers(dev, &cai, &cmd));
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    CHECK(vkBeginCommandBuffer(cmd, &begin));
    hairpipe::Instance* heads[] = {&head};
    OK(renderer.recordUpdate(cmd, 0, heads));
    OK(renderer.recordShadows(cmd, 0, hairpipe::Light{}, heads));
    barrier(cmd, color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    barrier(cmd, depth.image, VK_IMAGE_ASPECT_DEPTH_BIT, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
            VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
    VkRenderingAttachmentInfo ca{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO, nullptr, color.view, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
        VK_RESOLVE_MODE_NONE, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE};
    ca.clearValue.color = {{0.25f, 0.3f, 0.35f, 1.0f}};
    VkRenderingAttachmentInfo da{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO, nullptr, depth.view, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,
        VK_RESOLVE_MODE_NONE, VK_NULL_HANDLE, VK_IMAGE_LAYOUT_UNDEFINED, VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_DONT_CARE};
    da.clearValue.depthStencil = {1.0f, 0};
    VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO, nullptr, 0, {{0, 0}, {W, H}}, 1, 0, 1, &ca, &da};
    vkCmdBeginRendering(cmd, &ri);
    OK(renderer.recordDraw(cmd, 0, view, heads));
    vkCmdEndRendering(cmd);
    // 4. The colour into a host-visible buffer, then a PNG.
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, nullptr, 0, W * H * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT};
    VkBuffer buffer;
    CHECK(vkCreateBuffer(dev, &bci, nullptr, &buffer));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(dev, buffer, &req);
    VkMemoryAllocateInfo mai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, nullptr, req.size,
        memoryType(gpu, req.memoryTypeBits, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT)};
    VkDeviceMemory memory;
    CHECK(vkAllocateMemory(dev, &mai, nullptr, &memory));
    CHECK(vkBindBufferMemory(dev, buffer, memory, 0));
    barrier(cmd, color.image, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
            VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_COPY_BIT,
            VK_ACCESS_2_TRANSFER_READ_BIT);
    VkBufferImageCopy region{0, 0, 0, {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1}, {0, 0, 0}, {W, H, 1}};
    vkCmdCopyImageToBuffer(cmd, color.image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &region);
    CHECK(vkEndCommandBuffer(cmd));
    VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO, nullptr, 0, nullptr, nullptr, 1, &cmd};
    CHECK(vkQueueSubmit(queue, 1, &si, VK_NULL_HANDLE));
    CHECK(vkQueueWaitIdle(queue));
    void* pixels;
    CHECK(vkMapMemory(dev, memory, 0, VK_WHOLE_SIZE, 0, &pixels));
    if (!stbi_write_png("hello_hair.png", W, H, 4, pixels, W * 4)) return std::fprintf(stderr, "cannot write hello_hair.png\n"), 1;
    vkDestroyBuffer(dev, buffer, nullptr);
    vkFreeMemory(dev, memory, nullptr);
    vkDestroyCommandPool(dev, pool, nullptr);
  }  // hairpipe (instance, renderer, context) goes before the device
  for (Image* i : {&color, &depth}) {
    vkDestroyImageView(dev, i->view, nullptr);
    vkDestroyImage(dev, i->image, nullptr);
    vkFreeMemory(dev, i->memory, nullptr);
  }
  vkDestroyDevice(dev, nullptr);
  vkDestroyInstance(instance, nullptr);
  std::printf("hello_hair: wrote hello_hair.png (%u x %u)\n", W, H);
  return 0;
}
