// hairpipe::RasterTarget through the public headers: created for an application's depth image (made here
// with plain Vulkan through the loader's libvulkan.so.1, opened at run time: the build defines
// VK_NO_PROTOTYPES for hairpipe's own code), refused by another Renderer and once moved
// from, its motion image, its refusal to draw once its instances are gone, and handles that outlive their
// Renderer or go before it, all under validation without a message. The images it draws are compared with
// the Renderer's own target's in tests/render/raster_targets_test.cpp.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <dlfcn.h>
#include <vulkan/vulkan.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "hairpipe/hairpipe.h"
#include "tests/api/validated_context.h"

namespace {
using ::testing::HasSubstr;

template <class T>
std::string messageOf(const T& result) {
  EXPECT_FALSE(result.ok());
  return result.ok() ? std::string("(succeeded)") : result.message();
}

// The device functions the test's depth image needs, from the loader hairpipe's headless context uses.
struct DeviceFunctions {
  PFN_vkCreateImage createImage = nullptr;
  PFN_vkGetImageMemoryRequirements requirements = nullptr;
  PFN_vkAllocateMemory allocate = nullptr;
  PFN_vkBindImageMemory bind = nullptr;
  PFN_vkCreateImageView createView = nullptr;
  PFN_vkDestroyImageView destroyView = nullptr;
  PFN_vkDestroyImage destroyImage = nullptr;
  PFN_vkFreeMemory free = nullptr;
  void* loader = nullptr;

  DeviceFunctions(const DeviceFunctions&) = delete;
  DeviceFunctions& operator=(const DeviceFunctions&) = delete;
  ~DeviceFunctions() {
    if (loader) dlclose(loader);
  }
  explicit DeviceFunctions(const hairpipe::Context& ctx) {
    loader = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);  // already loaded: a reference more
    if (!loader) throw std::runtime_error("libvulkan.so.1 could not be opened");
    const auto instanceProc = reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(loader, "vkGetInstanceProcAddr"));
    const auto deviceProc =
        reinterpret_cast<PFN_vkGetDeviceProcAddr>(instanceProc(ctx.instance(), "vkGetDeviceProcAddr"));
    const auto device = [&](const char* name) { return deviceProc(ctx.device(), name); };
    createImage = reinterpret_cast<PFN_vkCreateImage>(device("vkCreateImage"));
    requirements = reinterpret_cast<PFN_vkGetImageMemoryRequirements>(device("vkGetImageMemoryRequirements"));
    allocate = reinterpret_cast<PFN_vkAllocateMemory>(device("vkAllocateMemory"));
    bind = reinterpret_cast<PFN_vkBindImageMemory>(device("vkBindImageMemory"));
    createView = reinterpret_cast<PFN_vkCreateImageView>(device("vkCreateImageView"));
    destroyView = reinterpret_cast<PFN_vkDestroyImageView>(device("vkDestroyImageView"));
    destroyImage = reinterpret_cast<PFN_vkDestroyImage>(device("vkDestroyImage"));
    free = reinterpret_cast<PFN_vkFreeMemory>(device("vkFreeMemory"));
  }
};

// A depth image as an application's main pass has it for the compute raster: D32, sampled, with a view.
struct DepthImage {
  DeviceFunctions vk;
  VkDevice device = VK_NULL_HANDLE;
  VkImage image = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkImageView view = VK_NULL_HANDLE;

  DepthImage(const hairpipe::Context& ctx, VkExtent2D extent) : vk(ctx), device(ctx.device()) {
    VkImageCreateInfo ii{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ii.imageType = VK_IMAGE_TYPE_2D;
    ii.format = VK_FORMAT_D32_SFLOAT;
    ii.extent = {extent.width, extent.height, 1};
    ii.mipLevels = ii.arrayLayers = 1;
    ii.samples = VK_SAMPLE_COUNT_1_BIT;
    ii.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
    EXPECT_EQ(vk.createImage(device, &ii, nullptr, &image), VK_SUCCESS);
    VkMemoryRequirements req;
    vk.requirements(device, image, &req);
    VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    while (!(req.memoryTypeBits & (1u << ai.memoryTypeIndex))) ++ai.memoryTypeIndex;
    EXPECT_EQ(vk.allocate(device, &ai, nullptr, &memory), VK_SUCCESS);
    EXPECT_EQ(vk.bind(device, image, memory, 0), VK_SUCCESS);
    VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vi.image = image;
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = ii.format;
    vi.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
    EXPECT_EQ(vk.createView(device, &vi, nullptr, &view), VK_SUCCESS);
  }
  ~DepthImage() {
    vk.destroyView(device, view, nullptr);
    vk.destroyImage(device, image, nullptr);
    vk.free(device, memory, nullptr);
  }
};

class RasterTargetApi : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_NO_FATAL_FAILURE(hairpipe::test::createValidatedContext(ctx_));
    hairpipe::Result<hairpipe::Asset> a = hairpipe::defaultHeadAsset({hairpipe::Density::Mode::Total, 8, 300, 7});
    ASSERT_TRUE(a.ok()) << a.message();
    asset_.emplace(std::move(a).value());
    depth_.emplace(*ctx_, kExtent);
  }
  void TearDown() override {
    if (!ctx_) return;
    EXPECT_TRUE(ctx_->waitIdle().ok());
    depth_.reset();  // the application's image, destroyed once the device is idle
    hairpipe::test::expectIdleAndSilent(*ctx_);
  }
  hairpipe::Renderer computeRenderer(bool motion = false) {
    hairpipe::RendererSettings s;
    s.formats = {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_1_BIT};
    s.raster = hairpipe::RasterMode::Compute;
    s.motionVectors = motion;
    hairpipe::Result<hairpipe::Renderer> r = hairpipe::Renderer::create(*ctx_, s);
    EXPECT_TRUE(r.ok()) << r.message();
    return std::move(r).value();
  }
  hairpipe::Instance instance(hairpipe::Renderer& renderer) {
    hairpipe::Result<hairpipe::Instance> i = renderer.createInstance(*asset_, {});
    EXPECT_TRUE(i.ok()) << i.message();
    return std::move(i).value();
  }
  static constexpr VkExtent2D kExtent{64, 48};
  std::optional<hairpipe::Context> ctx_;
  std::optional<hairpipe::Asset> asset_;
  std::optional<DepthImage> depth_;
};

TEST_F(RasterTargetApi, AnotherRendererAndAMovedFromTargetAreRefusedByName) {
  hairpipe::Renderer renderer = computeRenderer(), other = computeRenderer();
  hairpipe::Instance head = instance(renderer);
  hairpipe::Instance* heads[] = {&head};
  hairpipe::Result<hairpipe::RasterTarget> made = renderer.createRasterTarget(kExtent, depth_->view, heads);
  ASSERT_TRUE(made.ok()) << made.message();
  hairpipe::RasterTarget target = std::move(made).value();
  const hairpipe::View view = hairpipe::makeView({}, kExtent).value();
  // Refused before anything is recorded: a null command buffer suffices.
  EXPECT_THAT(messageOf(other.recordRaster(VK_NULL_HANDLE, 0, view, target)),
              HasSubstr("hairpipe::Renderer::recordRaster: the raster target belongs to another Renderer"));
  EXPECT_THAT(messageOf(other.recordComposite(VK_NULL_HANDLE, kExtent, target)), HasSubstr("another Renderer"));
  EXPECT_THAT(messageOf(other.motionImage(target)), HasSubstr("another Renderer"));
  EXPECT_THAT(messageOf(renderer.motionImage(target)), HasSubstr("motionVectors is off"));
  hairpipe::RasterTarget taken = std::move(target);
  EXPECT_THAT(messageOf(renderer.recordRaster(VK_NULL_HANDLE, 0, view, target)),
              HasSubstr("hairpipe::Renderer::recordRaster: the raster target was moved from"));
  EXPECT_THAT(messageOf(renderer.recordComposite(VK_NULL_HANDLE, kExtent, target)), HasSubstr("moved from"));
  hairpipe::View wide = view;
  wide.extent = {kExtent.width * 2, kExtent.height};
  EXPECT_THAT(messageOf(renderer.recordRaster(VK_NULL_HANDLE, 0, wide, taken)),
              HasSubstr("View.extent 128x48 differs from the raster target's 64x48"));
  // A target assigned over retires the one it held and takes the other's: with no frame recorded yet nothing
  // can be in flight, so the Renderer destroys the old one at once (tests/render/raster_targets_test.cpp
  // follows a retired target through frames in flight).
  hairpipe::RasterTarget second = std::move(renderer.createRasterTarget(kExtent, depth_->view, heads)).value();
  const std::uint64_t bothHeld = ctx_->allocatedBytes();
  taken = std::move(second);
  EXPECT_LT(ctx_->allocatedBytes(), bothHeld);
  EXPECT_THAT(messageOf(renderer.recordRaster(VK_NULL_HANDLE, 0, wide, second)), HasSubstr("moved from"));
  EXPECT_THAT(messageOf(renderer.recordRaster(VK_NULL_HANDLE, 0, wide, taken)), HasSubstr("View.extent 128x48"));
}

TEST_F(RasterTargetApi, ATargetHandsOutItsMotionImageAndRefusesToDrawOnceItsInstancesAreGone) {
  std::optional<hairpipe::Renderer> renderer(computeRenderer(true));
  std::optional<hairpipe::Instance> head(instance(*renderer));
  hairpipe::Instance* heads[] = {&*head};
  hairpipe::RasterTarget target = std::move(renderer->createRasterTarget(kExtent, depth_->view, heads)).value();
  const hairpipe::Result<hairpipe::Renderer::MotionImage> motion = renderer->motionImage(target);
  ASSERT_TRUE(motion.ok()) << motion.message();
  EXPECT_NE(motion.value().image, VK_NULL_HANDLE);
  EXPECT_EQ(motion.value().format, VK_FORMAT_R16G16_SFLOAT);
  EXPECT_EQ(motion.value().extent.width, kExtent.width);
  EXPECT_EQ(motion.value().extent.height, kExtent.height);
  // The Renderer's own target is another one: not set yet.
  EXPECT_THAT(messageOf(renderer->motionImage()), HasSubstr("setRasterTarget"));
  head.reset();  // the target's only instance: it is emptied
  EXPECT_THAT(messageOf(renderer->recordRaster(VK_NULL_HANDLE, 0, hairpipe::makeView({}, kExtent).value(), target)),
              HasSubstr("no instance to draw (its instances were destroyed, or a rebuild failed): create another"));
  EXPECT_THAT(messageOf(renderer->motionImage(target)), HasSubstr("no instance to draw"));
  // The handle outlives the Renderer's: it keeps what it needs, and goes after it.
  renderer.reset();
}
}  // namespace
