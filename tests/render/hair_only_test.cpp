// Hair only (InstanceSettings::drawHead false): hairpipe draws no proxy head, and the hair is depth-tested
// against what the application drew before it, in both rasterizers. The application's "character" here is
// a depth clear to the near plane over the left half of the frame, inside the rendering and before
// recordDraw: every hair pixel there must vanish, the right half must stay as it was.
#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <vector>

#include "compute/renderer/renderer.h"
#include "engine/vk/submit.h"
#include "samples/tools/offscreen_renderer.h"
#include "tests/support/small_frame.h"
#include "tests/support/vk_fixture.h"

using hp::test::VulkanTest;

namespace {
using hp::test::kSmallHeight;
using hp::test::kSmallWidth;

// The application's depth: the near plane (0) over the left half, as a character in front would leave it.
void clearLeftHalfToNear(const hp::vk::Context& ctx, VkCommandBuffer cmd) {
  VkClearAttachment depth{VK_IMAGE_ASPECT_DEPTH_BIT, 0, {}};
  depth.clearValue.depthStencil = {0.0f, 0};
  const VkClearRect rect{{{0, 0}, {kSmallWidth / 2, kSmallHeight}}, 0, 1};
  ctx.fn().vkCmdClearAttachments(cmd, 1, &depth, 1, &rect);
}

// Pixels of `image` that differ from `reference` by more than `tolerance` levels in a channel, in columns
// [x0, x1).
std::size_t differingPixels(const std::vector<std::uint8_t>& image, const std::vector<std::uint8_t>& reference,
                            std::uint32_t x0, std::uint32_t x1, int tolerance = 0) {
  std::size_t n = 0;
  for (std::uint32_t y = 0; y < kSmallHeight; ++y)
    for (std::uint32_t x = x0; x < x1; ++x) {
      const std::size_t px = (std::size_t(y) * kSmallWidth + x) * 4;
      for (int c = 0; c < 3; ++c)
        if (std::abs(int(image[px + c]) - int(reference[px + c])) > tolerance) {
          ++n;
          break;
        }
    }
  return n;
}

// Pixels in the skin's colour range (sRGB red above 110 and above blue by 25): the lit face and shoulders;
// the default brown hair stays far below it.
std::size_t skinPixels(const std::vector<std::uint8_t>& image) {
  std::size_t n = 0;
  for (std::size_t px = 0; px < image.size(); px += 4) n += image[px] > 110 && image[px] > image[px + 2] + 25;
  return n;
}

// Frames of one raster path: the background alone, the head with its hair, the hair only, and the hair only
// behind the application's depth on the left half.
struct Frames {
  std::vector<std::uint8_t> background, withHead, hairOnly, hairOnlyBehind;
};

Frames renderFrames(const hp::vk::Context& ctx, hp::RasterMode raster) {
  hp::render::OffscreenRenderer target(ctx, kSmallWidth, kSmallHeight, 1, raster);
  hp::RendererSettings settings;
  settings.formats = target.formats();
  settings.raster = raster;
  settings.opacity.resolution = 256;
  hp::Renderer renderer(ctx, settings);
  hp::InstanceSettings hairOnlySettings;
  hairOnlySettings.drawHead = false;
  const hp::HairAsset asset = hp::test::defaultHeadWithStrands(1500);
  auto withHead = renderer.createInstance(asset, {});
  auto hairOnly = renderer.createInstance(asset, hairOnlySettings);
  const hp::View view = hp::test::smallFrontView();
  std::uint64_t frame = 0;
  const auto render = [&](hp::HairInstance* instance, bool behind, bool update) {
    hp::HairInstance* const list[] = {instance};
    const std::span<hp::HairInstance* const> instances(list, instance ? 1 : 0);
    if (raster == hp::RasterMode::Compute && instance) target.attach(renderer, instances);
    const auto application = [&](VkCommandBuffer c) {
      if (behind) clearLeftHalfToNear(ctx, c);
    };
    hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      if (instance && update) renderer.recordUpdate(cmd, frame, instances);
      if (instance) renderer.recordShadows(cmd, frame, hp::LightSpec{}, instances);  // every frame
      if (raster == hp::RasterMode::Compute && instance) {
        target.record(cmd, renderer, frame, view, instances, 1.0f, nullptr, application);
      } else {
        target.record(cmd, [&](VkCommandBuffer c) {
          application(c);
          if (instance) renderer.recordDraw(c, frame, view, instances);
        }, 1.0f);
      }
    }, "hair only");
    ++frame;
    return target.readDisplay();
  };
  Frames f;
  f.background = render(nullptr, false, false);
  f.withHead = render(withHead.get(), false, true);
  render(hairOnly.get(), false, true);
  // The same strands twice (shadows and framing recorded again, the simulation not stepped): without and
  // with the application's depth in front of the left half.
  f.hairOnly = render(hairOnly.get(), false, false);
  f.hairOnlyBehind = render(hairOnly.get(), true, false);
  return f;
}

void expectHairOnly(const Frames& f, const char* path) {
  const std::uint32_t half = kSmallWidth / 2;
  const int tolerance = 2;
  const std::size_t skinWithHead = skinPixels(f.withHead), skinHairOnly = skinPixels(f.hairOnly);
  const std::size_t hairLeft = differingPixels(f.hairOnly, f.background, 0, half, tolerance);
  const std::size_t behindLeft = differingPixels(f.hairOnlyBehind, f.background, 0, half, tolerance);
  const std::size_t changedRight = differingPixels(f.hairOnlyBehind, f.hairOnly, half, kSmallWidth, tolerance);
  std::cout << path << ": skin pixels with head " << skinWithHead << ", hair only " << skinHairOnly
            << "; hair pixels in the left half " << hairLeft << ", behind the application's depth " << behindLeft
            << "; right half pixels changed by it " << changedRight << "\n";
  // The head is drawn with its instance (its face and shoulders) and not at all without it; the hair is.
  EXPECT_GT(skinWithHead, std::size_t(kSmallWidth * kSmallHeight / 20)) << path;
  EXPECT_EQ(skinHairOnly, 0u) << path;
  EXPECT_GT(hairLeft, std::size_t(kSmallWidth * kSmallHeight / 50)) << path;
  // Behind the application's depth nothing of the hair shows; beside it the frame is as before, up to the
  // compute rasterizer's run-to-run variation (fragments of equal depth meet in either order: a pixel or
  // two of identical frames moves by more than 2 levels; a broken depth test changes hundreds).
  EXPECT_EQ(behindLeft, 0u) << path;
  EXPECT_LE(changedRight, 8u) << path;
}
}  // namespace

TEST_F(VulkanTest, HairOnlyInstancesDrawNoHeadAndHideBehindTheApplicationsDepthGraphics) {
  expectHairOnly(renderFrames(*ctx, hp::RasterMode::Graphics), "graphics");
}

TEST_F(VulkanTest, HairOnlyInstancesDrawNoHeadAndHideBehindTheApplicationsDepthCompute) {
  expectHairOnly(renderFrames(*ctx, hp::RasterMode::Compute), "compute");
}
