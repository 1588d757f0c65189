// hp::Renderer with several hair instances: shared pipelines and LUTs, heads shadowing each other in the
// shared opacity maps (semantic image check), several views per frame, and frames in flight (3 frames,
// 2 in flight on one queue, a material change between them: sync-validation clean and equal to the same
// frames run one at a time), with retired resources destroyed after their last frame; two instances on the
// compute raster.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <array>
#include <thread>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "samples/tools/offscreen_renderer.h"
#include "compute/head/skin_transfer_buffer.h"
#include "compute/renderer/instance_preparation.h"
#include "compute/renderer/lut_build.h"
#include "compute/renderer/renderer.h"
#include "engine/core/shading/lut_cache.h"
#include "engine/core/shading/material_color.h"
#include "engine/vk/check.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "tests/support/device_call_counter.h"
#include "tests/support/frame_slots.h"
#include "tests/support/rgba_luminance.h"
#include "tests/support/vk_fixture.h"

using hp::test::VulkanTest;

namespace {
constexpr std::uint32_t kRendererWidth = 160, kRendererHeight = 96;

hp::HairAsset head(std::uint32_t strands) {
  hp::DensityOptions density;
  density.totalStrands = strands;
  return hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), density);
}

hp::HairMaterial blonde() {
  hp::HairMaterial m;
  m.absorption = hp::absorptionFromColor({0.85, 0.7, 0.45});
  return m;
}

hp::RendererSettings rendererSettings(const hp::render::OffscreenRenderer& target) {
  hp::RendererSettings s;
  s.formats = target.formats();
  s.raster = target.raster();
  s.opacity.resolution = 256;
  s.opacity.strandOpacity = 0.3f;  // 3,000 strands stand in for the default 20,000 at 0.04
  return s;
}

hp::View frontView(float targetX) {
  hp::CameraSpec cam;
  cam.orbitDeg = 0.0f;
  cam.elevationDeg = 0.0f;
  cam.distance = 1.1f;
  cam.target = {targetX, -0.05f, 0.0f};
  return hp::View{hp::orbitCamera(cam, float(kRendererWidth) / kRendererHeight), {kRendererWidth, kRendererHeight}, false, 0};
}

using hp::test::pixelsApart;
using hp::test::rgbaLinearSum;

// Sum of linear luminance over the columns [x0, x1).
double columnsLuminance(const std::vector<std::uint8_t>& rgba, std::uint32_t x0, std::uint32_t x1) {
  double sum = 0.0;
  for (std::uint32_t y = 0; y < kRendererHeight; ++y)
    for (std::uint32_t x = x0; x < x1; ++x) sum += rgbaLinearSum(rgba, std::size_t(y) * kRendererWidth + x);
  return sum;
}
}  // namespace

TEST_F(VulkanTest, SecondInstanceBuildsNoPipelinesAndSharesItsMaterialsLuts) {
  hp::render::OffscreenRenderer target(*ctx, 32, 32, 1);
  hp::Renderer renderer(*ctx, rendererSettings(target));
  const hp::HairAsset asset = head(500);
  auto first = renderer.createInstance(asset, {});
  const std::size_t pipelines = renderer.pipelines().pipelineCount();
  EXPECT_GE(pipelines, 9u);  // simulate, tessellate, interpolate, bounds, 2 opacity, head, ribbons, lines
  auto second = renderer.createInstance(asset, {}, glm::translate(glm::mat4(1.0f), {0.4f, 0.0f, 0.0f}));
  EXPECT_EQ(renderer.pipelines().pipelineCount(), pipelines);
  EXPECT_EQ(&first->marschner(), &second->marschner());
  hp::InstanceSettings other;
  other.material = blonde();
  auto third = renderer.createInstance(asset, other);
  EXPECT_NE(&first->marschner(), &third->marschner());
  EXPECT_EQ(renderer.pipelines().pipelineCount(), pipelines);
}

TEST_F(VulkanTest, TwoInstancesWithDifferentAssetsAndMaterialsShadowEachOther) {
  hp::render::OffscreenRenderer target(*ctx, kRendererWidth, kRendererHeight, 1);
  hp::Renderer renderer(*ctx, rendererSettings(target));
  // `near` stands between `far` and a light low on the +X side; both are drawn in every frame.
  const glm::mat4 nearHead = glm::translate(glm::mat4(1.0f), {0.36f, 0.0f, 0.0f});
  hp::InstanceSettings nearSettings;
  nearSettings.material = blonde();
  auto nearHair = renderer.createInstance(head(1500), nearSettings, nearHead);
  auto farHair = renderer.createInstance(head(3000), {});
  hp::HairInstance* both[] = {farHair.get(), nearHair.get()};
  hp::HairInstance* farOnly[] = {farHair.get()};
  hp::HairInstance* nearOnly[] = {nearHair.get()};
  hp::LightSpec light;
  light.direction = glm::normalize(glm::vec3(1.0f, 0.15f, 0.0f));
  const hp::View view = frontView(0.18f);  // far head on the left half, near head on the right

  std::uint64_t frame = 1;
  auto render = [&](std::span<hp::HairInstance* const> casters) {
    hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
      if (frame == 1) renderer.recordUpdate(cmd, frame, both);  // the same strands in every image
      renderer.recordShadows(cmd, frame, light, casters);
      target.record(cmd, [&](VkCommandBuffer c) { renderer.recordDraw(c, frame, view, both); }, 1.0f);
    }, "two heads");
    ++frame;
    return target.readDisplay();
  };
  const std::vector<std::uint8_t> shadowedByNear = render(both);
  const std::vector<std::uint8_t> alone = render(farOnly);
  const std::vector<std::uint8_t> nearCasting = render(nearOnly);
  const double farShadowed = columnsLuminance(shadowedByNear, 0, kRendererWidth / 2);
  const double farAlone = columnsLuminance(alone, 0, kRendererWidth / 2);
  // The near head and its hair take the light off the far head's lit side (measured 0.55 of the light it gets alone).
  EXPECT_LT(farShadowed, 0.8 * farAlone) << farShadowed << " vs " << farAlone;
  std::cout << "far head lit / shadowed by the near one: " << farAlone << " / " << farShadowed << "\n";
  // The far head casts nothing on the near one (the light comes from the near side): the near head is
  // no darker than when it casts alone. (It is brighter, measured 1.16x: one framing over both heads
  // spreads the 16 slices over twice the depth, so the 1-slice lookup bias skips more self-shadowing;
  // compute/shadows/README.md "Several instances".)
  const double nearBoth = columnsLuminance(shadowedByNear, kRendererWidth * 3 / 4, kRendererWidth);
  const double nearAlone = columnsLuminance(nearCasting, kRendererWidth * 3 / 4, kRendererWidth);
  EXPECT_GT(nearAlone, 0.0);
  EXPECT_GE(nearBoth, 0.98 * nearAlone) << nearBoth << " vs " << nearAlone;
}

TEST_F(VulkanTest, SeveralViewsOfOneFrameReuseItsShadows) {
  hp::render::OffscreenRenderer left(*ctx, kRendererWidth, kRendererHeight, 1), right(*ctx, kRendererWidth, kRendererHeight, 1);
  hp::Renderer renderer(*ctx, rendererSettings(left));
  auto hair = renderer.createInstance(head(1000), {});
  hp::HairInstance* one[] = {hair.get()};
  hp::View a = frontView(0.0f), b = frontView(0.0f);
  hp::CameraSpec side;
  side.orbitDeg = 90.0f;
  b.camera = hp::orbitCamera(side, float(kRendererWidth) / kRendererHeight);
  b.index = 1;
  hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    renderer.recordUpdate(cmd, 7, one);
    renderer.recordShadows(cmd, 7, hp::LightSpec{}, one);
    left.record(cmd, [&](VkCommandBuffer c) { renderer.recordDraw(c, 7, a, one); }, 1.0f);
    right.record(cmd, [&](VkCommandBuffer c) { renderer.recordDraw(c, 7, b, one); }, 1.0f);
  }, "two views");
  // Each view kept its own camera: the images differ, and the front view equals a frame drawn alone.
  const auto front = left.readDisplay();
  EXPECT_GT(pixelsApart(front, right.readDisplay(), 0), std::size_t(kRendererWidth * kRendererHeight / 20));
  hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    left.record(cmd, [&](VkCommandBuffer c) { renderer.recordDraw(c, 7, a, one); }, 1.0f);
  }, "front again");
  EXPECT_EQ(pixelsApart(front, left.readDisplay(), 0), 0u);
  b.index = renderer.settings().maxViewsPerFrame;
  EXPECT_THROW(renderer.recordDraw(VK_NULL_HANDLE, 7, b, one), hp::Error);
  // A frame number that goes back is refused before anything is recorded (retirement counts frames).
  try {
    renderer.recordUpdate(VK_NULL_HANDLE, 6, one);
    ADD_FAILURE() << "frame 6 after frame 7 was accepted";
  } catch (const hp::Error& e) {
    EXPECT_NE(std::string(e.what()).find("frame 6 comes after frame 7 was recorded"), std::string::npos) << e.what();
  }
}

namespace {

// Three frames of two heads into three targets, `inFlight` frames pending at most; the material of the
// second head changes after frame 2 was submitted (the queue submissions and waits it makes counted).
// Returns the three images.
std::vector<std::vector<std::uint8_t>> threeFrames(const hp::vk::Context& ctx, std::uint32_t inFlight,
                                                   std::size_t* retiredAfterChange, std::size_t* retiredAtEnd,
                                                   std::size_t* queueCallsOfChange = nullptr) {
  std::vector<std::unique_ptr<hp::render::OffscreenRenderer>> targets;
  for (int i = 0; i < 3; ++i) targets.push_back(std::make_unique<hp::render::OffscreenRenderer>(ctx, 96, 64, 1));
  hp::RendererSettings settings = rendererSettings(*targets[0]);
  settings.framesInFlight = 2;
  hp::Renderer renderer(ctx, settings);
  auto a = renderer.createInstance(head(800), {});
  auto b = renderer.createInstance(head(600), {}, glm::translate(glm::mat4(1.0f), {0.3f, 0.0f, 0.0f}));
  hp::HairInstance* both[] = {a.get(), b.get()};
  hp::CameraSpec cam;
  cam.target = {0.15f, -0.05f, 0.0f};
  const hp::View view{hp::orbitCamera(cam, 1.5f), {96, 64}, false, 0};
  hp::test::FrameSlots slots(ctx, inFlight);
  std::unique_ptr<hp::test::DeviceCallCounter> counter;  // the change and the frame that applies it
  for (std::uint64_t frame = 0; frame < 3; ++frame) {
    const std::size_t slot = frame % inFlight;
    VkCommandBuffer cmd = slots.begin(slot);  // waits for frame - inFlight
    if (frame == 2) {
      counter = std::make_unique<hp::test::DeviceCallCounter>(ctx);
      const auto start = std::chrono::steady_clock::now();
      const std::size_t retiredBeforeChange = renderer.retiredCount();
      b->setMaterial(blonde(), hp::LutMode::Float);  // frame 1 may still be in flight
      EXPECT_EQ(renderer.retiredCount(), retiredBeforeChange);  // nothing changes until the tables are built
      std::cout << "setMaterial (float LUTs built on a worker thread): "
                << std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count()
                << " ms on the calling thread\n";
      EXPECT_TRUE(b->materialPending());
      b->waitForMaterial();  // the tables built: this frame's recordUpdate applies them
    }
    const double t = frame / 60.0;
    a->setMotion({glm::mat4(1.0f), glm::rotate(glm::mat4(1.0f), float(0.2 * t), {0, 1, 0}), t, false});
    const std::size_t retiredBefore = renderer.retiredCount();
    renderer.recordUpdate(cmd, frame, both);
    if (frame == 2) *retiredAfterChange = renderer.retiredCount() - retiredBefore;
    renderer.recordShadows(cmd, frame, hp::LightSpec{}, both);
    targets[frame]->record(cmd, [&](VkCommandBuffer c) { renderer.recordDraw(c, frame, view, both); }, 1.0f);
    slots.submit(slot);
    if (counter && queueCallsOfChange) *queueCallsOfChange = counter->calls().queue;
    counter.reset();
  }
  for (std::size_t s = 0; s < inFlight; ++s) slots.wait(s);
  VkCommandBuffer cmd = slots.begin(0);
  renderer.recordUpdate(cmd, 4, both);  // frame 4 >= retired at 1 + 2 in flight: the old LUTs go
  *retiredAtEnd = renderer.retiredCount();
  slots.submit(0);
  slots.wait(0);
  std::vector<std::vector<std::uint8_t>> images;
  for (auto& t : targets) images.push_back(t->readDisplay());
  return images;
}
}  // namespace

TEST_F(VulkanTest, ThreeFramesTwoInFlightWithAMaterialChangeEqualTheFramesRunOneAtATime) {
  std::size_t retiredAfterChange = 0, retiredAtEnd = 0, queueCalls = 99;
  const auto inFlight = threeFrames(*ctx, 2, &retiredAfterChange, &retiredAtEnd, &queueCalls);
  // The change's tables are built on a worker; the next recordUpdate uploads them in the application's
  // command buffer: the application's queue sees no submission and no wait from setMaterial or that frame.
  EXPECT_EQ(queueCalls, 0u);
  // That recordUpdate retires the old LUT textures and strand pass of the changed head and the executed
  // upload batch (3), less what frame 0 retired and is done by then.
  EXPECT_GE(retiredAfterChange, 2u);
  EXPECT_EQ(retiredAtEnd, 0u);
  const auto oneAtATime = threeFrames(*ctx, 1, &retiredAfterChange, &retiredAtEnd);
  for (std::size_t f = 0; f < 3; ++f) EXPECT_EQ(pixelsApart(inFlight[f], oneAtATime[f], 0), 0u) << "frame " << f;
  // The change took effect in frame 3 only.
  EXPECT_GT(pixelsApart(inFlight[1], inFlight[2], 0), 100u);
}

namespace {
// Over the columns [x0, x1) of the compute raster's hair image: pixels with hair (alpha above 0.05: thin
// heads, ~0.05 px strands) and the summed premultiplied radiance.
struct HairColumns {
  std::size_t pixels = 0;
  double radiance = 0.0;
};
HairColumns hairColumns(const hp::vk::Context& ctx, const hp::Renderer& renderer, std::uint32_t x0, std::uint32_t x1) {
  const auto bytes = hp::vk::readbackImage(ctx, renderer.rasterImage(), hp::vk::ImageUse::FragmentSampled);
  const auto rgb = hp::render::rgbOfHalfRgba(bytes, {kRendererWidth, kRendererHeight}, 0, 3);
  const auto alpha = hp::render::rgbOfHalfRgba(bytes, {kRendererWidth, kRendererHeight}, 3, 1);
  HairColumns h;
  for (std::uint32_t y = 0; y < kRendererHeight; ++y)
    for (std::uint32_t x = x0; x < x1; ++x) {
      const std::size_t px = std::size_t(y) * kRendererWidth + x;
      h.pixels += alpha.values[px] > 0.05f;
      h.radiance += rgb.values[px * 3] + rgb.values[px * 3 + 1] + rgb.values[px * 3 + 2];
    }
  return h;
}
}  // namespace

// The compute raster's strands take their width from the view's extent and its tiles from the target's: a
// view of another size is refused before anything is recorded (it drew strands of the wrong width).
TEST_F(VulkanTest, ARasterViewOfAnotherExtentThanItsTargetIsRefused) {
  hp::render::OffscreenRenderer target(*ctx, kRendererWidth, kRendererHeight, 1, hp::RasterMode::Compute);
  hp::Renderer renderer(*ctx, rendererSettings(target));
  auto hair = renderer.createInstance(head(300), {});
  hp::HairInstance* one[] = {hair.get()};
  target.attach(renderer, one);
  hp::View view = frontView(0.0f);
  view.extent = {kRendererWidth / 2, kRendererHeight};
  try {
    renderer.recordRaster(VK_NULL_HANDLE, 0, view);
    ADD_FAILURE() << "a view of another extent was accepted";
  } catch (const hp::Error& e) {
    EXPECT_NE(std::string(e.what()).find("View.extent 80x96 differs from the raster target's 160x96"), std::string::npos)
        << e.what();
  }
}

// Two views of one frame with the same View::index share the instance's frame block (host memory the draws
// read at execution): the second would draw the first with its camera. Refused before anything is recorded;
// the same view again, another index, or the next frame pass.
TEST_F(VulkanTest, TwoViewsOfAFrameWithOneIndexAreRefused) {
  hp::render::OffscreenRenderer target(*ctx, kRendererWidth, kRendererHeight, 1);
  hp::Renderer renderer(*ctx, rendererSettings(target));
  auto hair = renderer.createInstance(head(300), {});
  hp::HairInstance* one[] = {hair.get()};
  const hp::View left = frontView(-0.1f), right = frontView(0.1f);
  hp::View rightAtOne = right;
  rightAtOne.index = 1;
  std::string refusal;
  hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    renderer.recordUpdate(cmd, 1, one);
    renderer.recordShadows(cmd, 1, hp::LightSpec{}, one);
    target.record(cmd, [&](VkCommandBuffer c) {
      renderer.recordDraw(c, 1, left, one);
      renderer.recordDraw(c, 1, left, one);        // the same view again: the same block
      renderer.recordDraw(c, 1, rightAtOne, one);  // another index
      try {
        renderer.recordDraw(c, 1, right, one);
      } catch (const hp::Error& e) {
        refusal = e.what();
      }
    }, 1.0f);
  }, "one index, two views");
  EXPECT_NE(refusal.find("View.index 0 already drew another view in frame 1"), std::string::npos) << refusal;
  hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    renderer.recordShadows(cmd, 2, hp::LightSpec{}, one);
    target.record(cmd, [&](VkCommandBuffer c) { renderer.recordDraw(c, 2, right, one); }, 1.0f);  // the next frame
  }, "next frame");
}

// The middleware API on the compute raster: two heads side by side in one set of tile lists, both drawn;
// a target of one head draws that head only; after a material change the target (kept) draws the changed
// head's hair brighter and the other's unchanged. Sync-validation clean (fixture).
TEST_F(VulkanTest, TwoInstancesOnTheComputeRasterAreBothDrawnAndFollowAMaterialChange) {
  hp::render::OffscreenRenderer target(*ctx, kRendererWidth, kRendererHeight, 1, hp::RasterMode::Compute);
  hp::Renderer renderer(*ctx, rendererSettings(target));
  auto left = renderer.createInstance(head(600), {});
  auto right = renderer.createInstance(head(500), {}, glm::translate(glm::mat4(1.0f), {0.3f, 0.0f, 0.0f}));
  hp::HairInstance* both[] = {left.get(), right.get()};
  const hp::View view = frontView(0.15f);
  const auto frame = [&](std::uint64_t f) {
    hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
      renderer.recordUpdate(cmd, f, both);
      renderer.recordShadows(cmd, f, hp::LightSpec{}, both);
      target.record(cmd, renderer, f, view, both, 1.0f);
    }, "compute raster instances");
  };
  const std::uint32_t half = kRendererWidth / 2;
  target.attach(renderer, both);
  frame(0);
  const HairColumns leftHair = hairColumns(*ctx, renderer, 0, half), rightHair = hairColumns(*ctx, renderer, half, kRendererWidth);
  std::cout << "hair pixels: left " << leftHair.pixels << ", right " << rightHair.pixels << "\n";
  // Each head drawn: 0.5% of the frame above alpha 0.05 (216 and 151 pixels of 15,360; the sparser 500
  // strands fell under 1% when overlapping strands stopped adding up as independent ones, raster_fine).
  // What separates drawn from not drawn is the detach below (a detached head keeps < 1/4 of its pixels).
  EXPECT_GT(leftHair.pixels, std::size_t(kRendererWidth * kRendererHeight / 200));
  EXPECT_GT(rightHair.pixels, std::size_t(kRendererWidth * kRendererHeight / 200));

  hp::HairInstance* leftOnly[] = {left.get()};
  target.attach(renderer, leftOnly);
  frame(1);
  EXPECT_GT(hairColumns(*ctx, renderer, 0, half).pixels, leftHair.pixels * 9 / 10);
  EXPECT_LT(hairColumns(*ctx, renderer, half, kRendererWidth).pixels, rightHair.pixels / 4);

  target.attach(renderer, both);
  const VkImage image = renderer.rasterImage().handle();
  right->setMaterial(blonde(), hp::LutMode::Float);  // the target rebinds the new LUTs (not rebuilt)
  right->waitForMaterial();                           // built on a worker: frame 2 applies it
  frame(2);
  EXPECT_EQ(renderer.rasterImage().handle(), image);
  const double leftChange = hairColumns(*ctx, renderer, 0, half).radiance / leftHair.radiance;
  const double rightChange = hairColumns(*ctx, renderer, half, kRendererWidth).radiance / rightHair.radiance;
  std::cout << "hair radiance after / before the material change: left " << leftChange << ", right " << rightChange
            << "\n";
  EXPECT_NEAR(leftChange, 1.0, 0.1);
  EXPECT_GT(rightChange, 1.5);
}

namespace {
// Five frames of one head on the compute raster, two in flight on one queue; with `change`, the material
// changes to blonde while frame 1 is recorded (its tables built before frame 1 is submitted), so frame 2
// applies it and rebinds slot 0 right after frame 1 was submitted, frame 1 still running on slot 1's sets;
// without, it is blonde from the start.
// Returns the images of frames 3 and 4 (drawn with the second and the first frame slot's descriptor sets)
// and, with `change`, counts what the change and the frames after it cost the device.
std::vector<std::vector<std::uint8_t>> computeFramesInFlight(const hp::vk::Context& ctx, bool change,
                                                             hp::test::DeviceCalls* costOfChange = nullptr,
                                                             bool* sameTarget = nullptr) {
  hp::render::OffscreenRenderer target(ctx, 96, 64, 1, hp::RasterMode::Compute);
  hp::RendererSettings settings = rendererSettings(target);
  settings.framesInFlight = 2;
  hp::Renderer renderer(ctx, settings);
  auto hair = renderer.createInstance(head(500), {});
  if (!change) hair->setMaterial(blonde(), hp::LutMode::Float);  // before the frame loop: applied at once
  hp::HairInstance* one[] = {hair.get()};
  target.attach(renderer, one);
  const VkImage image = renderer.rasterImage().handle();
  hp::CameraSpec cam;
  const hp::View view{hp::orbitCamera(cam, 1.5f), {96, 64}, false, 0};
  hp::test::FrameSlots slots(ctx, 2);
  std::unique_ptr<hp::test::DeviceCallCounter> counter;
  std::vector<std::vector<std::uint8_t>> images;
  for (std::uint64_t frame = 0; frame < 5; ++frame) {
    VkCommandBuffer cmd = slots.begin(frame % 2);  // waits for frame - 2
    const double t = frame / 60.0;
    hair->setMotion({glm::mat4(1.0f), glm::rotate(glm::mat4(1.0f), float(0.2 * t), {0, 1, 0}), t, false});
    renderer.recordUpdate(cmd, frame, one);
    renderer.recordShadows(cmd, frame, hp::LightSpec{}, one);
    if (change && frame == 1) {  // in the frame loop: built on a worker, applied by frame 2's recordUpdate
      counter = std::make_unique<hp::test::DeviceCallCounter>(ctx);
      hair->setMaterial(blonde(), hp::LutMode::Float);
      hair->waitForMaterial();
    }
    target.record(cmd, renderer, frame, view, one, 1.0f);
    slots.submit(frame % 2);
    if (counter && frame == 3) {  // both slots' sets rebound (frames 2 and 3)
      if (costOfChange) *costOfChange = counter->calls();
      counter.reset();
    }
    if (frame < 3) continue;
    slots.wait(0);
    slots.wait(1);
    images.push_back(target.readDisplay());
  }
  if (sameTarget) *sameTarget = renderer.rasterImage().handle() == image;
  return images;
}
}  // namespace

// A material change on the compute raster keeps the raster target: each frame slot's descriptor sets take
// the new LUTs when that slot is next recorded (its last frame complete), under sync validation with a
// frame in flight, so every frame after the change is the frame of a head blonde from the start (up to the
// compute raster's run-to-run noise: segments in one depth bin composite in the order their atomics
// listed them, which moves a few 8-bit pixels by one step; a slot left on the old LUTs darkens the whole
// head by a third, TwoInstancesOnTheComputeRasterAreBothDrawnAndFollowAMaterialChange); and the
// change and the two frames that rebind create no pipeline and no descriptor pool, and make no queue
// submission or wait of their own (the new LUTs are uploaded in frame 2's command buffer).
TEST_F(VulkanTest, AMaterialChangeOnTheComputeRasterRebindsItsLutsWithoutRebuilding) {
  hp::test::DeviceCalls cost;
  bool sameTarget = false;
  const auto changed = computeFramesInFlight(*ctx, true, &cost, &sameTarget);
  const auto fromStart = computeFramesInFlight(*ctx, false);
  std::cout << "material change and two frames: " << cost.pipelines << " pipelines, " << cost.descriptorPools
            << " descriptor pools, " << cost.allocations << " allocations, " << cost.queue
            << " queue calls\n";
  EXPECT_TRUE(sameTarget);
  EXPECT_EQ(cost.queue, 0u);
  EXPECT_EQ(cost.pipelines, 0u);
  EXPECT_EQ(cost.descriptorPools, 0u);
  ASSERT_EQ(changed.size(), 2u);
  for (std::size_t f = 0; f < 2; ++f) {
    double sumChanged = 0.0, sumFromStart = 0.0;
    for (std::size_t px = 0; px < changed[f].size() / 4; ++px) {
      sumChanged += hp::test::rgbaLinearSum(changed[f], px);
      sumFromStart += hp::test::rgbaLinearSum(fromStart[f], px);
    }
    std::cout << "frame " << f + 3 << ": " << pixelsApart(changed[f], fromStart[f], 0)
              << " pixels differ, brightness ratio " << sumChanged / sumFromStart << "\n";
    EXPECT_LT(pixelsApart(changed[f], fromStart[f], 0), changed[f].size() / 4 / 100) << "frame " << f + 3;
    EXPECT_NEAR(sumChanged / sumFromStart, 1.0, 0.002) << "frame " << f + 3;
  }
}

// Two changes between the same two frames, one frame in flight: the second replaces the first while its
// tables are still being built (no upload of the first ever runs); the second material is what is drawn,
// and a repeated change to it records nothing.
TEST_F(VulkanTest, TwoMaterialChangesBetweenFramesDrawTheSecond) {
  hp::render::OffscreenRenderer target(*ctx, 96, 64, 1);
  hp::RendererSettings settings = rendererSettings(target);
  settings.framesInFlight = 1;
  hp::Renderer renderer(*ctx, settings);
  auto hair = renderer.createInstance(head(400), {});
  hp::HairInstance* one[] = {hair.get()};
  hp::CameraSpec cam;
  const hp::View view{hp::orbitCamera(cam, 1.5f), {96, 64}, false, 0};
  const auto frame = [&](std::uint64_t f) {
    hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
      if (f == 0) renderer.recordUpdate(cmd, f, one);  // the same strands in every frame
      renderer.recordShadows(cmd, f, hp::LightSpec{}, one);
      target.record(cmd, [&](VkCommandBuffer c) { renderer.recordDraw(c, f, view, one); }, 1.0f);
    }, "two changes");
    return target.readDisplay();
  };
  frame(0);
  hp::HairMaterial red;
  red.absorption = hp::absorptionFromColor({0.9, 0.2, 0.1});
  hair->setMaterial(red, hp::LutMode::Float);         // built on a worker
  hair->setMaterial(blonde(), hp::LutMode::Float);    // replaces it before it is applied
  hair->waitForMaterial();
  const auto changed = frame(1);
  EXPECT_FALSE(hair->materialPending());
  hair->setMaterial(blonde(), hp::LutMode::Float);    // no change: nothing recorded
  const auto again = frame(2);
  EXPECT_EQ(pixelsApart(changed, again, 0), 0u);
}

namespace {
// A Renderer of one 400-strand head, one frame in flight, drawing 96 x 64 frames (recordUpdate in frame 0
// only: the same strands in every frame).
struct OneHeadFrames {
  explicit OneHeadFrames(const hp::vk::Context& context)
      : ctx(context), target(context, 96, 64, 1), renderer(context, settings(target)),
        hair(renderer.createInstance(head(400), {})) {}
  static hp::RendererSettings settings(const hp::render::OffscreenRenderer& target) {
    hp::RendererSettings s = rendererSettings(target);
    s.framesInFlight = 1;
    return s;
  }
  std::vector<std::uint8_t> frame(std::uint64_t f) {
    hp::HairInstance* one[] = {hair.get()};
    hp::CameraSpec cam;
    const hp::View view{hp::orbitCamera(cam, 1.5f), {96, 64}, false, 0};
    hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      if (f == 0) renderer.recordUpdate(cmd, f, one);
      renderer.recordShadows(cmd, f, hp::LightSpec{}, one);
      target.record(cmd, [&](VkCommandBuffer c) { renderer.recordDraw(c, f, view, one); }, 1.0f);
    }, "one head");
    return target.readDisplay();
  }
  const hp::vk::Context& ctx;
  hp::render::OffscreenRenderer target;
  hp::Renderer renderer;
  std::unique_ptr<hp::HairInstance> hair;
};

hp::HairMaterial tinted(double red) {
  hp::HairMaterial m;
  m.absorption = hp::absorptionFromColor({red, 0.3, 0.2});
  return m;
}
}  // namespace

// A change in the frame loop whose tables cannot be uploaded (no device memory left in the budget) leaves
// the former material drawn and says why; a later change clears that and applies.
TEST_F(VulkanTest, AMaterialChangeThatCannotApplyIsReportedAndTheFormerMaterialStays) {
  OneHeadFrames heads(*ctx);
  const auto before = heads.frame(0);
  ctx->setDeviceMemoryBudget(ctx->allocatedBytes() + 256 * 1024);  // the frames' readback, not the tables
  heads.hair->setMaterial(tinted(0.9), hp::LutMode::Float);
  heads.hair->waitForMaterial();
  const auto refused = heads.frame(1);
  EXPECT_FALSE(heads.hair->materialPending());
  EXPECT_NE(heads.hair->materialError().find("did not apply"), std::string::npos) << heads.hair->materialError();
  EXPECT_NE(heads.hair->materialError().find("budget"), std::string::npos) << heads.hair->materialError();
  EXPECT_EQ(pixelsApart(before, refused, 0), 0u);
  ctx->setDeviceMemoryBudget(0);
  heads.hair->setMaterial(tinted(0.9), hp::LutMode::Float);
  EXPECT_TRUE(heads.hair->materialError().empty());
  heads.hair->waitForMaterial();
  const auto applied = heads.frame(2);
  EXPECT_TRUE(heads.hair->materialError().empty()) << heads.hair->materialError();
  EXPECT_GT(pixelsApart(before, applied, 0), 100u);
}

// Eight changes queued in the frame loop while the worker is held build one table: the first seven are
// replaced before their turn and skipped; the last is what is drawn.
TEST_F(VulkanTest, MaterialChangesReplacedBeforeTheirTurnAreNotBuilt) {
  OneHeadFrames heads(*ctx);
  heads.frame(0);
  const std::uint64_t builtBefore = hp::LutBuild::builtCount();
  {
    const hp::LutWorkerHold hold;
    for (int k = 1; k <= 8; ++k) heads.hair->setMaterial(tinted(0.05 * k), hp::LutMode::Float);
  }
  heads.hair->waitForMaterial();
  const std::uint64_t built = hp::LutBuild::builtCount() - builtBefore;
  std::cout << built << " of 8 material builds ran\n";
  EXPECT_EQ(built, 1u);
  heads.frame(1);
  EXPECT_FALSE(heads.hair->materialPending());
  EXPECT_TRUE(heads.hair->settings().material == tinted(0.05 * 8));
}

// An instance destroyed in the frame loop is retired (frames in flight may read it); once the application
// has waited for its frames, releaseRetired gives its device memory back at once, and the frame numbers may
// start again.
TEST_F(VulkanTest, RetiredInstancesAreReleasedWhenTheApplicationSaysItsFramesAreDone) {
  OneHeadFrames heads(*ctx);
  heads.frame(0);
  auto second = heads.renderer.createInstance(head(400), {});
  heads.frame(1);  // its uploads run in this frame
  const std::uint64_t withTwo = ctx->allocatedBytes();
  const std::size_t retiredBefore = heads.renderer.retiredCount();
  heads.renderer.destroyInstance(std::move(second));  // in the frame loop: retired, not freed
  EXPECT_GT(heads.renderer.retiredCount(), retiredBefore);
  EXPECT_EQ(ctx->allocatedBytes(), withTwo);
  heads.renderer.releaseRetired();  // frames 0 and 1 were waited for (submitAndWait)
  EXPECT_EQ(heads.renderer.retiredCount(), 0u);
  EXPECT_LT(ctx->allocatedBytes(), withTwo);
  heads.frame(0);  // the numbering may start again after releaseRetired; the remaining head still draws
  heads.frame(3);
  hp::HairInstance* one[] = {heads.hair.get()};
  EXPECT_THROW(heads.renderer.recordUpdate(VK_NULL_HANDLE, 2, one), hp::Error);  // going back is refused again
}

// An instance's CPU start-up work prepared on a loading thread (its tables, their parameter block, its head's
// transfer: a mesh and material no earlier test used): createInstance on this thread then computes none of
// them (without prepareInstance it computes all three).
TEST_F(VulkanTest, AnInstancePreparedOnAnotherThreadComputesNoTablesOrTransferWhenCreated) {
  hp::HairAsset asset = head(400);
  asset.head.positions[0] *= 1.001f;  // a mesh this process has not seen
  hp::InstanceSettings settings;
  settings.material.absorption = hp::absorptionFromColor({0.31, 0.27, 0.19});  // tables not made yet
  const auto made = [] {
    return std::array<std::uint64_t, 3>{hp::sharedLutsMade(), hp::sharedMarschnerParamsMade(),
                                        hp::render::skinTransfersComputed()};
  };
  std::thread loader([&] { hp::prepareInstance(asset, settings); });
  loader.join();
  const auto prepared = made();
  hp::render::OffscreenRenderer target(*ctx, 64, 48, 1);
  hp::Renderer renderer(*ctx, rendererSettings(target));
  auto hair = renderer.createInstance(asset, settings);
  EXPECT_EQ(made(), prepared);  // createInstance made none of them
  settings.material.eta = std::nan("");
  EXPECT_THROW(hp::prepareInstance(asset, settings), hp::Error);
}

namespace {
// The default-orbit frame of one head, on a target whose depth has the given convention (cleared to 0 and
// the projection's planes swapped where reversed), graphics or compute raster.
std::vector<std::uint8_t> frameWithDepthConvention(const hp::vk::Context& ctx, hp::RasterMode raster, bool reversed,
                                                   std::uint32_t samples) {
  hp::render::OffscreenRenderer target(ctx, kRendererWidth, kRendererHeight, samples, raster, reversed);
  hp::Renderer renderer(ctx, rendererSettings(target));
  auto hair = renderer.createInstance(head(800), {});
  hp::HairInstance* one[] = {hair.get()};
  hp::View view = frontView(0.0f);
  if (reversed) {  // the same planes as orbitCamera's, swapped: near at depth 1, far at 0
    const float distance = 1.1f;
    view.camera.proj = glm::perspectiveRH_ZO(view.camera.fovY, float(kRendererWidth) / kRendererHeight,
                                             20.0f * distance, 0.02f * distance);
  }
  if (raster == hp::RasterMode::Compute) target.attach(renderer, one);
  hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    renderer.recordUpdate(cmd, 0, one);
    renderer.recordShadows(cmd, 0, hp::LightSpec{}, one);
    if (raster == hp::RasterMode::Compute) target.record(cmd, renderer, 0, view, one, 1.0f);
    else target.record(cmd, [&](VkCommandBuffer c) { renderer.recordDraw(c, 0, view, one); }, 1.0f);
  }, "depth convention");
  return target.readDisplay();
}
}  // namespace

// A reversed-Z application (depth cleared to 0, nearer larger, a reversed projection) gets the frame a
// forward one gets, with either raster and, on the compute raster, a single- or 4-sample depth: the heads' and
// ribbons' depth test turned, the compute raster reading the depth and the hair's projected depth as 1 - z.
// Without that the reversed frame has no head (every fragment fails LESS_OR_EQUAL against 0). Measured on
// lavapipe: no pixel differs (graphics), 0-43 of 15,360 (compute: the order within a depth bin follows its
// atomics, as between two forward runs); asserted: under 1%, brightness within 0.5%.
TEST_F(VulkanTest, AReversedDepthApplicationGetsTheForwardFrame) {
  const std::pair<hp::RasterMode, std::uint32_t> cases[] = {
      {hp::RasterMode::Graphics, 1}, {hp::RasterMode::Compute, 1}, {hp::RasterMode::Compute, 4}};
  for (const auto& [raster, samples] : cases) {
    const auto forward = frameWithDepthConvention(*ctx, raster, false, samples);
    const auto reversed = frameWithDepthConvention(*ctx, raster, true, samples);
    double forwardSum = 0.0, reversedSum = 0.0;
    for (std::size_t px = 0; px < forward.size() / 4; ++px) {
      forwardSum += hp::test::rgbaLinearSum(forward, px);
      reversedSum += hp::test::rgbaLinearSum(reversed, px);
    }
    const std::size_t differing = pixelsApart(forward, reversed, 0);
    std::cout << (raster == hp::RasterMode::Compute ? "compute" : "graphics") << " x" << samples << ": " << differing
              << " pixels differ, brightness ratio " << reversedSum / forwardSum << "\n";
    EXPECT_LT(differing, forward.size() / 4 / 100);
    EXPECT_NEAR(reversedSum / forwardSum, 1.0, 0.005);
  }
}

// An instance's frame blocks carry its physical material's mean forward albedo and the forward density
// with dual scattering (what the hair passes on to and from the skin, frame_shadows.glsl
// hairTransmittance), and nothing with single scattering or the paper's model.
TEST_F(VulkanTest, FrameBlocksCarryTheHairsForwardAlbedoWithDualScatteringOnly) {
  hp::render::OffscreenRenderer target(*ctx, 64, 48, 1);
  hp::Renderer renderer(*ctx, rendererSettings(target));
  hp::InstanceSettings settings;
  settings.material = blonde();
  auto hair = renderer.createInstance(head(300), settings);
  hp::render::LookSettings look = hair->settings().look;
  look.scattering = hp::render::Scattering::Dual;
  const glm::vec4 dual = hair->frameBlock(hp::CameraMatrices{}, {64, 48}, hp::render::FrameLights{}, look).hairForward;
  const glm::vec4 mean = hair->marschner().params().forwardMean;
  std::cout << "blonde mean forward albedo " << mean.x << " " << mean.y << " " << mean.z << "\n";
  EXPECT_EQ(glm::vec3(dual), glm::vec3(mean));
  EXPECT_EQ(dual.w, hp::gpu::MARSCHNER_FORWARD_DENSITY);
  EXPECT_GT(mean.x, mean.z);  // blonde passes more red on than blue
  for (int c = 0; c < 3; ++c) EXPECT_TRUE(mean[c] > 0.0f && mean[c] < 1.0f) << "channel " << c;
  look.scattering = hp::render::Scattering::Single;
  EXPECT_EQ(hair->frameBlock(hp::CameraMatrices{}, {64, 48}, hp::render::FrameLights{}, look).hairForward, glm::vec4(0.0f));
  settings.lutMode = hp::LutMode::Float;  // the paper's model: no multiple-scattering tables
  auto paper = renderer.createInstance(head(300), settings);
  look.scattering = hp::render::Scattering::Dual;
  EXPECT_EQ(glm::vec3(paper->frameBlock(hp::CameraMatrices{}, {64, 48}, hp::render::FrameLights{}, look).hairForward),
            glm::vec3(0.0f));
}
