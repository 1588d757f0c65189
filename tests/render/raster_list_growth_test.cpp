// Growing tile lists (RasterSettings::growLists, public RendererSettings::growRasterLists): a target's lists
// start small; a view that asks for more than they hold drops entries until the slot it was drawn with comes
// round again (framesInFlight frames later), when the lists grow to twice its need, and from then on the frame
// is the one the worst-case lists draw. Under synchronization validation.
#include <gtest/gtest.h>

#include <iostream>
#include <memory>
#include <vector>

#include "compute/renderer/renderer.h"
#include "engine/vk/submit.h"
#include "samples/tools/offscreen_renderer.h"
#include "tests/support/rgba_luminance.h"
#include "tests/support/small_frame.h"
#include "tests/support/vk_fixture.h"

using hp::test::pixelsApart;
using hp::test::VulkanTest;

namespace {
struct Frame {
  hp::compute::RasterStats stats;
  std::vector<std::uint8_t> display;
};

// `count` frames of the small frame's head (3,000 strands) from far off, each submitted and waited for (so
// every earlier frame is complete, as the frame contract asks), with growing lists that start at one entry
// per segment (this view asks ~1.1 per segment: the default start, 2, would hold it) or the worst-case lists.
std::vector<Frame> frames(const hp::vk::Context& ctx, bool grow, int count) {
  hp::render::OffscreenRenderer target(ctx, hp::test::kSmallWidth, hp::test::kSmallHeight, 1, hp::RasterMode::Compute);
  hp::RendererSettings s;
  s.formats = target.formats();
  s.raster = hp::RasterMode::Compute;
  s.opacity.resolution = 128;
  s.rasterSettings.growLists = grow;
  s.rasterSettings.listStartPerSegment = 1;
  hp::Renderer renderer(ctx, s);
  auto hair = renderer.createInstance(hp::test::defaultHeadWithStrands(3000), {});
  hp::HairInstance* one[] = {hair.get()};
  target.attach(renderer, one);
  std::vector<Frame> out;
  for (int f = 0; f < count; ++f) {
    hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      renderer.recordUpdate(cmd, std::uint64_t(f), one);
      renderer.recordShadows(cmd, std::uint64_t(f), hp::LightSpec{}, one);
      target.record(cmd, renderer, std::uint64_t(f), hp::test::smallFrontView(1.6f), one, 1.0f);
    }, "list growth frame");
    out.push_back({renderer.rasterStats(), target.readDisplay()});
  }
  return out;
}
}  // namespace

TEST_F(VulkanTest, GrowingTileListsGrowOnceAFrameAsksForMoreAndThenDrawAsTheWorstCaseListsDo) {
  constexpr int kFrames = 4;  // framesInFlight 2: frame 0's slot comes round at frame 2
  const std::vector<Frame> grown = frames(*ctx, true, kFrames);
  const std::vector<Frame> worst = frames(*ctx, false, kFrames);
  for (int f = 0; f < kFrames; ++f)
    std::cout << "frame " << f << ": " << grown[f].stats.kept + grown[f].stats.droppedByCapacity << " entries asked, capacity "
              << grown[f].stats.listCapacity << ", dropped " << grown[f].stats.droppedByCapacity << "; worst-case lists "
              << worst[f].stats.listCapacity << ", dropped " << worst[f].stats.droppedByCapacity << "\n";
  const std::uint32_t start = grown.front().stats.listCapacity;
  EXPECT_LT(start, worst.front().stats.listCapacity / 4);  // 1 per segment against 8
  // Frames 0 and 1 ask for more than the start holds and drop entries (the slots' last frames asked nothing).
  for (int f = 0; f < 2; ++f) {
    EXPECT_EQ(grown[f].stats.listCapacity, start);
    EXPECT_GT(grown[f].stats.droppedByCapacity, 0u);
  }
  // From frame 2 (frame 0's slot, whose need is known) the lists have grown and nothing is dropped.
  for (int f = 2; f < kFrames; ++f) {
    EXPECT_GT(grown[f].stats.listCapacity, start);
    EXPECT_LT(grown[f].stats.listCapacity, worst[f].stats.listCapacity);
    EXPECT_EQ(grown[f].stats.droppedByCapacity, 0u);
    EXPECT_EQ(worst[f].stats.droppedByCapacity, 0u);
  }
  // The images: a grown frame is the worst-case lists' within the compute raster's run-to-run noise (segments
  // of one depth bin composite in their atomics' order; 0 pixels here on lavapipe). A frame that dropped
  // entries differs by more (87 pixels: the farthest bins of the densest tiles, mostly behind nearer hair).
  const std::size_t pixels = grown.back().display.size() / 4;
  const std::size_t droppedApart = pixelsApart(grown[0].display, worst[0].display, 1);
  const std::size_t grownApart = pixelsApart(grown.back().display, worst.back().display, 1);
  std::cout << "pixels apart from the worst-case lists' frame: " << droppedApart << " while dropping, " << grownApart
            << " once grown, of " << pixels << "\n";
  EXPECT_LE(grownApart, pixels / 50);
}
