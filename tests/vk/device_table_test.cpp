// hairpipe calls device functions through its own per-device table (Context::fn()): the global pointers
// of its volk copy, loaded for one device (here the fixture's, standing for an application that calls
// through them), stay as they are when hairpipe adopts another device. An application's own loader or
// volk symbols are other symbols altogether (the installed archives define no vk*: Package.* tests).
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "engine/core/hair/default_head.h"
#include "compute/renderer/renderer.h"
#include "engine/vk/check.h"
#include "engine/vk/submit.h"
#include "tests/support/vk_fixture.h"

using hp::test::VulkanTest;

namespace {
// Counts the calls that reach volk's global vkCreateBuffer and forwards them.
int globalCreateBufferCalls = 0;
PFN_vkCreateBuffer realCreateBuffer = nullptr;
VKAPI_ATTR VkResult VKAPI_CALL countingCreateBuffer(VkDevice device, const VkBufferCreateInfo* info,
                                                    const VkAllocationCallbacks* allocator, VkBuffer* buffer) {
  ++globalCreateBufferCalls;
  return realCreateBuffer(device, info, allocator, buffer);
}

// Puts the application's volk global back however the test ends.
struct RestoreCreateBuffer {
  ~RestoreCreateBuffer() { vkCreateBuffer = realCreateBuffer; }
};

// A second Vulkan 1.3 device on the same physical device, as an application would hand it over; its own
// functions come from a table the test keeps (the application's globals stay on the first device).
struct SecondDevice {
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  VolkDeviceTable fn{};
  SecondDevice(VkPhysicalDevice physical, std::uint32_t family) {
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
    volkLoadDeviceTable(&fn, device);
    fn.vkGetDeviceQueue(device, family, 0, &queue);
  }
  ~SecondDevice() { fn.vkDestroyDevice(device, nullptr); }
};
}  // namespace

TEST_F(VulkanTest, AdoptingADeviceLeavesTheApplicationsVolkFunctionsAlone) {
  // The application: volk's globals are loaded for its device (the fixture's), and it wraps one of them.
  ASSERT_EQ(volkGetLoadedDevice(), ctx->device());
  realCreateBuffer = vkCreateBuffer;
  RestoreCreateBuffer restore;
  vkCreateBuffer = countingCreateBuffer;
  globalCreateBufferCalls = 0;
  {
    SecondDevice second(ctx->physicalDevice(), ctx->queueFamily());
    auto adopted = hp::vk::Context::adopt(
        {vkGetInstanceProcAddr, ctx->instance(), ctx->physicalDevice(), second.device, ctx->queueFamily(), second.queue,
         true});
    EXPECT_EQ(adopted->fn().vkCreateBuffer, second.fn.vkCreateBuffer);
    // hairpipe's work on the adopted device: a renderer, an instance (buffers, images, pipelines, uploads)
    // and one recorded frame of simulation.
    hp::RendererSettings rs;
    rs.formats = {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_1_BIT};
    hp::Renderer renderer(*adopted, rs);
    hp::DensityOptions density;
    density.totalStrands = 300;
    auto head = renderer.createInstance(hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), density), {});
    hp::HairInstance* heads[] = {head.get()};
    hp::vk::submitAndWait(*adopted, [&](VkCommandBuffer cmd) { renderer.recordUpdate(cmd, 0, heads); }, "frame");
    EXPECT_EQ(volkGetLoadedDevice(), ctx->device());
    EXPECT_EQ(vkCreateBuffer, &countingCreateBuffer);  // volkLoadDevice would have replaced the wrapper
    EXPECT_EQ(globalCreateBufferCalls, 0);             // every hairpipe buffer went through its own table
  }
  // The application's globals still drive its own device.
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 256;
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  ASSERT_EQ(vkCreateBuffer(ctx->device(), &info, nullptr, &buffer), VK_SUCCESS);
  EXPECT_EQ(globalCreateBufferCalls, 1);
  vkDestroyBuffer(ctx->device(), buffer, nullptr);
}
