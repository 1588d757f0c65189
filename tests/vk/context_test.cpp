#include <gtest/gtest.h>

#include "engine/core/error.h"
#include "engine/vk/buffer.h"
#include "engine/vk/check.h"
#include "engine/vk/context.h"
#include "engine/vk/device_probe.h"
#include "tests/support/vk_fixture.h"

using hp::test::VulkanTest;

TEST_F(VulkanTest, CreatesAVulkan13DeviceWithAGraphicsComputeQueue) {
  EXPECT_GE(ctx->properties().apiVersion, VK_API_VERSION_1_3);
  EXPECT_NE(ctx->queue(), VK_NULL_HANDLE);
  EXPECT_TRUE(ctx->validationEnabled());
  EXPECT_TRUE(ctx->selection().chosen.has_value());
}

// Proves the fixture can fail: an invalid call must be captured by the validation log.
TEST_F(VulkanTest, ValidationCaptureReportsAnInvalidCall) {
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = 0;  // VUID-VkBufferCreateInfo-size-00912: size must be greater than 0
  info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkResult r = vkCreateBuffer(ctx->device(), &info, nullptr, &buffer);
  if (r == VK_SUCCESS && buffer) vkDestroyBuffer(ctx->device(), buffer, nullptr);
  auto messages = log->messages();
  ASSERT_FALSE(messages.empty());
  EXPECT_NE(log->describeProblems().find("00912"), std::string::npos) << log->describeProblems();
  EXPECT_GE(takeValidationProblems(), 1u);
}

TEST(VulkanContext, UnknownDeviceRequestFailsAndListsDevices) {
  hp::vk::ContextOptions options;
  options.device = "nosuchdevice";
  try {
    hp::vk::Context::createHeadless(options);
    FAIL() << "expected hp::Error";
  } catch (const hp::Error& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("nosuchdevice"), std::string::npos) << msg;
    EXPECT_NE(msg.find("available devices"), std::string::npos) << msg;
  }
}

TEST(VulkanCheck, FailureNamesTheCallAndTheResult) {
  try {
    hp::vk::check(VK_ERROR_OUT_OF_DEVICE_MEMORY, "vkAllocateMemory(device, ...)");
    FAIL() << "expected hp::Error";
  } catch (const hp::Error& e) {
    std::string msg = e.what();
    EXPECT_NE(msg.find("vkAllocateMemory"), std::string::npos);
    EXPECT_NE(msg.find("VK_ERROR_OUT_OF_DEVICE_MEMORY"), std::string::npos);
  }
  EXPECT_NO_THROW(hp::vk::check(VK_SUCCESS, "vkFoo"));
}

// Device loss is the one failure a caller may recover from by making a new device: it has its own type,
// still an hp::Error for everyone else; other failures are plain hp::Error.
TEST(VulkanCheck, DeviceLossIsTellableApartByType) {
  EXPECT_THROW(hp::vk::check(VK_ERROR_DEVICE_LOST, "vkQueueSubmit2(queue, ...)"), hp::vk::DeviceLost);
  try {
    hp::vk::check(VK_ERROR_DEVICE_LOST, "vkWaitForFences(device, ...)");
  } catch (const hp::Error& e) {
    EXPECT_NE(std::string(e.what()).find("vkWaitForFences(device, ...) failed: VK_ERROR_DEVICE_LOST"), std::string::npos) << e.what();
  }
  try {
    hp::vk::check(VK_ERROR_OUT_OF_HOST_MEMORY, "vkCreateBuffer(device, ...)");
    FAIL() << "expected hp::Error";
  } catch (const hp::vk::DeviceLost&) {
    FAIL() << "only VK_ERROR_DEVICE_LOST is a DeviceLost";
  } catch (const hp::Error&) {
  }
}

namespace {
// Forwards volk's global vkGetPhysicalDeviceProperties2 and then reports no subgroup operation in any stage,
// as a device without them would.
PFN_vkGetPhysicalDeviceProperties2 realProperties2 = nullptr;
VKAPI_ATTR void VKAPI_CALL propertiesWithoutSubgroups(VkPhysicalDevice device, VkPhysicalDeviceProperties2* props) {
  realProperties2(device, props);
  for (auto* next = static_cast<VkBaseOutStructure*>(props->pNext); next; next = next->pNext)
    if (next->sType == VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES) {
      auto* subgroups = reinterpret_cast<VkPhysicalDeviceSubgroupProperties*>(next);
      subgroups->supportedStages = 0;
      subgroups->supportedOperations = 0;
    }
}
struct RestoreProperties2 {
  ~RestoreProperties2() { vkGetPhysicalDeviceProperties2 = realProperties2; }
};
}  // namespace

// The passes reduce through subgroups: a device whose compute shaders lack those operations is unfit, and
// says so by name.
TEST_F(VulkanTest, ADeviceWithoutComputeSubgroupOperationsIsRefusedByName) {
  realProperties2 = vkGetPhysicalDeviceProperties2;
  RestoreProperties2 restore;
  vkGetPhysicalDeviceProperties2 = propertiesWithoutSubgroups;
  EXPECT_FALSE(hp::vk::computeSubgroupOperations(ctx->physicalDevice()));
  const std::vector<std::string> reasons = hp::vk::unfitReasons(ctx->physicalDevice());
  ASSERT_EQ(reasons.size(), 1u);
  EXPECT_EQ(reasons[0], "subgroup operations basic, ballot and arithmetic in compute shaders");
}

// An application's device handed to hairpipe: adopt() checks what it can and never waits idle on it.
TEST_F(VulkanTest, AdoptedDeviceIsCheckedAndNeverWaitedIdle) {
  hp::vk::ExternalDevice ext{vkGetInstanceProcAddr, ctx->instance(), ctx->physicalDevice(), ctx->device(),
                             ctx->queueFamily(), ctx->queue(), true};
  {
    auto adopted = hp::vk::Context::adopt(ext);
    EXPECT_THROW(adopted->waitIdle(), hp::Error);
  }
  ext.queueFamily = 99;
  try {
    hp::vk::Context::adopt(ext);
    FAIL() << "adopted a missing queue family";
  } catch (const hp::Error& e) {
    EXPECT_NE(std::string(e.what()).find("queue family 99"), std::string::npos) << e.what();
  }
  ext.queueFamily = ctx->queueFamily();
  ext.device = VK_NULL_HANDLE;
  EXPECT_THROW(hp::vk::Context::adopt(ext), hp::Error);
}

TEST_F(VulkanTest, RequirementsNameWhatTheApplicationEnablesAndTheDeviceMeetsThem) {
  const hp::vk::DeviceRequirements r = hp::vk::requirements();
  EXPECT_EQ(r.apiVersion, VK_API_VERSION_1_3);
  ASSERT_EQ(r.features.size(), 2u);
  EXPECT_NE(r.features[0].find("dynamicRendering"), std::string::npos);
  EXPECT_NE(r.features[1].find("synchronization2"), std::string::npos);
  EXPECT_NE(r.subgroups.find("arithmetic"), std::string::npos);
  EXPECT_TRUE(hp::vk::computeSubgroupOperations(ctx->physicalDevice()));
  EXPECT_TRUE(hp::vk::unfitReasons(ctx->physicalDevice()).empty());
}

TEST_F(VulkanTest, DeviceMemoryHeldIsCountedAndGivenBack) {
  const std::uint64_t before = ctx->allocatedBytes();
  {
    hp::vk::Buffer b(*ctx, 1 << 20, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, hp::vk::MemoryKind::DeviceLocal, "counted");
    EXPECT_GE(ctx->allocatedBytes(), before + (1u << 20));
    hp::vk::Buffer moved = std::move(b);
    EXPECT_GE(ctx->allocatedBytes(), before + (1u << 20));
  }
  EXPECT_EQ(ctx->allocatedBytes(), before);
}
