// The frame loop's order (compute/renderer/renderer.h): a recordUpdate computes an instance's strands before
// anything draws them, a frame's recordShadows comes before its recordDraw and recordRaster, and
// recordComposite draws at its target's extent after its recordRaster; each broken order is refused by name before anything is
// recorded. An instance destroyed inside a frame is still drawn by that frame (its shadows hold it) and is gone
// from the next, without a refused call. Under synchronization validation.
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "compute/renderer/renderer.h"
#include "engine/core/error.h"
#include "engine/vk/submit.h"
#include "samples/tools/offscreen_renderer.h"
#include "tests/support/refusal.h"
#include "tests/support/small_frame.h"
#include "tests/support/vk_fixture.h"

using hp::test::VulkanTest;

namespace {
using hp::test::refusalOf;

hp::RendererSettings orderSettings(const hp::render::OffscreenRenderer& target) {
  return hp::test::computeRendererSettings(target.formats());
}

struct OrderScene {
  explicit OrderScene(const hp::vk::Context& ctx)
      : target(ctx, hp::test::kSmallWidth, hp::test::kSmallHeight, 1, hp::RasterMode::Compute),
        renderer(ctx, orderSettings(target)),
        hair(renderer.createInstance(hp::test::defaultHeadWithStrands(500), {})) {
    target.attach(renderer, one());
  }
  std::vector<hp::HairInstance*> one() const { return {hair.get()}; }
  // A whole frame in order: update, shadows, then the heads, the raster and the composite.
  void recordFrame(VkCommandBuffer cmd, std::uint64_t frame, const hp::View& view) {
    renderer.recordUpdate(cmd, frame, one());
    renderer.recordShadows(cmd, frame, hp::LightSpec{}, one());
    target.record(cmd, renderer, frame, view, one(), 1.0f);
  }
  void drawFrame(const hp::vk::Context& ctx, std::uint64_t frame, const hp::View& view) {
    hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) { recordFrame(cmd, frame, view); }, "frame in order");
  }
  hp::render::OffscreenRenderer target;
  hp::Renderer renderer;
  std::unique_ptr<hp::HairInstance> hair;
};
}  // namespace

TEST_F(VulkanTest, ADrawOrRasterWithoutItsFramesShadowsIsRefused) {
  OrderScene s(*ctx);
  const hp::View view = hp::test::smallFrontView(1.6f);
  const std::vector<hp::HairInstance*> one = s.one();
  hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    s.renderer.recordUpdate(cmd, 0, one);
    EXPECT_NE(refusalOf([&] { s.renderer.recordDraw(cmd, 0, view, one); }).find("frame 0 has no recordShadows"),
              std::string::npos);
    EXPECT_NE(refusalOf([&] { s.renderer.recordRaster(cmd, 0, view); }).find("frame 0 has no recordShadows"),
              std::string::npos);
    s.renderer.recordShadows(cmd, 0, hp::LightSpec{}, one);
    s.target.record(cmd, s.renderer, 0, view, one, 1.0f);  // in order: drawn
  }, "frame 0");
  hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    s.renderer.recordUpdate(cmd, 1, one);  // frame 0's shadows are not frame 1's
    EXPECT_NE(refusalOf([&] { s.renderer.recordRaster(cmd, 1, view); }).find("frame 1 has no recordShadows"),
              std::string::npos);
  }, "frame 1 without its shadows");
}

TEST_F(VulkanTest, StrandsNoUpdateComputedAreRefusedUntilOneDoes) {
  OrderScene s(*ctx);
  const hp::View view = hp::test::smallFrontView(1.6f);
  const std::vector<hp::HairInstance*> one = s.one();
  const std::string notComputed = "instance 0 has strands no recordUpdate has computed yet";
  hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    EXPECT_NE(refusalOf([&] { s.renderer.recordShadows(cmd, 0, hp::LightSpec{}, one); }).find(notComputed),
              std::string::npos);
    s.recordFrame(cmd, 0, view);
  }, "frame 0");
  // New strands (another density) between frames: their buffers hold nothing until the next update.
  s.hair->setStrands(hp::test::defaultHeadWithStrands(800).topology, s.hair->settings().strands);
  hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    EXPECT_NE(refusalOf([&] { s.renderer.recordShadows(cmd, 1, hp::LightSpec{}, one); }).find(notComputed),
              std::string::npos);
    s.recordFrame(cmd, 1, view);
  }, "frame 1");
}

TEST_F(VulkanTest, ACompositeOfAnotherExtentThanItsTargetIsRefused) {
  OrderScene s(*ctx);
  const std::string message = refusalOf([&] { s.renderer.recordComposite(VK_NULL_HANDLE, {80, 96}); });
  EXPECT_NE(message.find("the extent 80x96 differs from the raster target's 160x96"), std::string::npos) << message;
}

// The composite draws the target's image as recordRaster last left it: without this frame's recordRaster it
// would put the previous frame's hair over this frame's heads.
TEST_F(VulkanTest, ACompositeWithoutItsFramesRasterIsRefused) {
  OrderScene s(*ctx);
  const hp::View view = hp::test::smallFrontView(1.6f);
  const std::vector<hp::HairInstance*> one = s.one();
  const VkExtent2D extent{hp::test::kSmallWidth, hp::test::kSmallHeight};
  const std::string notDrawn = "the raster target has not drawn this frame";
  EXPECT_NE(refusalOf([&] { s.renderer.recordComposite(VK_NULL_HANDLE, extent); }).find(notDrawn), std::string::npos);
  s.drawFrame(*ctx, 0, view);  // raster, then composite: drawn
  hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    s.renderer.recordUpdate(cmd, 1, one);
    s.renderer.recordShadows(cmd, 1, hp::LightSpec{}, one);
    EXPECT_NE(refusalOf([&] { s.renderer.recordComposite(cmd, extent); }).find(notDrawn), std::string::npos);
  }, "frame 1 without its raster");
}

// Two heads side by side on one raster target; the right one destroyed after frame 2's shadows. That frame
// still draws it (no call refused), the next frame's first record call rebuilds the target without it. With one
// frame in flight the instance is freed by that very call (before the rebuild); with `releaseBetween` the
// application frees what was retired between the frames, the rebuild still waiting.
namespace {
void destroyInsideAFrame(const hp::vk::Context& ctx, std::uint32_t framesInFlight, bool releaseBetween) {
  hp::render::OffscreenRenderer target(ctx, hp::test::kSmallWidth, hp::test::kSmallHeight, 1, hp::RasterMode::Compute);
  hp::RendererSettings settings = orderSettings(target);
  settings.framesInFlight = framesInFlight;
  hp::Renderer renderer(ctx, settings);
  const hp::HairAsset asset = hp::test::defaultHeadWithStrands(500);
  auto left = renderer.createInstance(asset, {}, glm::translate(glm::mat4(1.0f), {-0.16f, 0.0f, 0.0f}));
  auto right = renderer.createInstance(asset, {}, glm::translate(glm::mat4(1.0f), {0.16f, 0.0f, 0.0f}));
  std::vector<hp::HairInstance*> both = {left.get(), right.get()}, kept = {left.get()};
  target.attach(renderer, both);
  const hp::View view = hp::test::smallFrontView(1.3f);
  // Hair pixels in the right head's half (clear of the left head), per frame.
  const auto rightHair = [&] {
    const std::vector<float> coverage = renderer.rasterCoverage();
    std::size_t pixels = 0;
    for (std::uint32_t y = 0; y < hp::test::kSmallHeight; ++y)
      for (std::uint32_t x = hp::test::kSmallWidth / 2 + 8; x < hp::test::kSmallWidth; ++x)
        pixels += coverage[std::size_t(y) * hp::test::kSmallWidth + x] > 0.05f;
    return pixels;
  };
  const auto frame = [&](std::uint64_t f, const std::vector<hp::HairInstance*>& instances) {
    hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      renderer.recordUpdate(cmd, f, instances);
      renderer.recordShadows(cmd, f, hp::LightSpec{}, instances);
      target.record(cmd, renderer, f, view, instances, 1.0f);
    }, "frame");
    return rightHair();
  };
  frame(0, both);
  const std::size_t before = frame(1, both);
  std::string frame2;
  hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    renderer.recordUpdate(cmd, 2, both);
    renderer.recordShadows(cmd, 2, hp::LightSpec{}, both);
    renderer.destroyInstance(std::move(right));  // despawned mid-frame, after the shadows hold it
    frame2 = refusalOf([&] { target.record(cmd, renderer, 2, view, kept, 1.0f); });
  }, "frame 2");
  const std::size_t during = rightHair();
  if (releaseBetween) renderer.releaseRetired();  // every frame was waited for
  const std::size_t after = frame(3, kept);
  std::cout << framesInFlight << " frame(s) in flight" << (releaseBetween ? ", retired released" : "")
            << ": right head's hair pixels " << before << " before, " << during << " in the frame that destroyed it, "
            << after << " after\n";
  EXPECT_EQ(frame2, "(accepted)");
  EXPECT_GT(before, 100u);
  EXPECT_GT(during, before / 2);  // more: its head, which hid some, is not drawn (the application drew `kept`)
  EXPECT_EQ(after, 0u);
}
}  // namespace

TEST_F(VulkanTest, AnInstanceDestroyedInsideAFrameIsDrawnByItAndGoneFromTheNext) {
  destroyInsideAFrame(*ctx, 2, false);
}
TEST_F(VulkanTest, AnInstanceDestroyedInsideAFrameWithOneFrameInFlightOrReleasedBetweenFrames) {
  destroyInsideAFrame(*ctx, 1, false);
  destroyInsideAFrame(*ctx, 2, true);
}

// An engine that records its passes into secondary command buffers: recordChanges, first in the frame's
// primary, executes the work a change left waiting (here new strands: their buffers' uploads and the raster
// target's rebuild), so the frame's recordUpdate and recordShadows, recorded into a secondary, execute none
// (vkCmdExecuteCommands in a secondary is invalid: the validation layer would say so and fail the test).
TEST_F(VulkanTest, AfterRecordChangesTheUpdateAndShadowsMayBeRecordedIntoASecondary) {
  OrderScene s(*ctx);
  const hp::View view = hp::test::smallFrontView(1.6f);
  const std::vector<hp::HairInstance*> one = s.one();
  s.drawFrame(*ctx, 0, view);
  s.hair->setStrands(hp::test::defaultHeadWithStrands(800).topology, s.hair->settings().strands);
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandPoolCreateInfo pi{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pi.queueFamilyIndex = ctx->queueFamily();
  ASSERT_EQ(vkCreateCommandPool(ctx->device(), &pi, nullptr, &pool), VK_SUCCESS);
  VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  ai.commandPool = pool;
  ai.level = VK_COMMAND_BUFFER_LEVEL_SECONDARY;
  ai.commandBufferCount = 1;
  VkCommandBuffer secondary = VK_NULL_HANDLE;
  ASSERT_EQ(vkAllocateCommandBuffers(ctx->device(), &ai, &secondary), VK_SUCCESS);
  hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer primary) {
    s.renderer.recordChanges(primary, 1, one);
    VkCommandBufferInheritanceInfo inheritance{VK_STRUCTURE_TYPE_COMMAND_BUFFER_INHERITANCE_INFO};
    VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    begin.pInheritanceInfo = &inheritance;
    ASSERT_EQ(vkBeginCommandBuffer(secondary, &begin), VK_SUCCESS);
    s.renderer.recordUpdate(secondary, 1, one);
    s.renderer.recordShadows(secondary, 1, hp::LightSpec{}, one);
    ASSERT_EQ(vkEndCommandBuffer(secondary), VK_SUCCESS);
    vkCmdExecuteCommands(primary, 1, &secondary);
    s.target.record(primary, s.renderer, 1, view, one, 1.0f);
  }, "frame 1: update and shadows in a secondary");
  vkDestroyCommandPool(ctx->device(), pool, nullptr);
  EXPECT_EQ(s.renderer.rasterStats().droppedByCapacity, 0u);
  EXPECT_GT(s.renderer.rasterStats().kept, 0u);  // the rebuilt target drew the new strands
}
