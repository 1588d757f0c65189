// Growing tile lists (RasterSettings::growLists, public RendererSettings::growRasterLists): a target's lists
// start small; a view that asks for more than they hold drops entries until the slot it was drawn with comes
// round again (framesInFlight frames later), when the lists grow to twice its need, and from then on the frame
// is the one the worst-case lists draw. Under synchronization validation.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <vector>

#include "compute/renderer/renderer.h"
#include "engine/vk/submit.h"
#include "samples/tools/offscreen_renderer.h"
#include "tests/support/frame_slots.h"
#include "tests/support/rgba_luminance.h"
#include "tests/support/small_frame.h"
#include "tests/support/vk_fixture.h"

using hp::test::pixelsApart;
using hp::test::VulkanTest;

namespace {
struct GrowthFrame {
  hp::compute::RasterStats stats;
  std::vector<std::uint8_t> display;
  std::vector<float> coverage;  // per pixel
};

// Per band of 8 rows (a row of tiles), the hair's coverage summed over its pixels.
std::vector<double> bandCoverage(const std::vector<float>& coverage) {
  std::vector<double> bands((hp::test::kSmallHeight + 7) / 8, 0.0);
  for (std::size_t p = 0; p < coverage.size(); ++p) bands[p / hp::test::kSmallWidth / 8] += coverage[p];
  return bands;
}

hp::RendererSettings listSettings(const hp::render::OffscreenRenderer& target, bool grow) {
  hp::RendererSettings s;
  s.formats = target.formats();
  s.raster = hp::RasterMode::Compute;
  s.opacity.resolution = 128;
  s.rasterSettings.growLists = grow;
  s.rasterSettings.listStartPerSegment = 1;
  return s;
}

// `count` frames of the small frame's head (3,000 strands) from far off, each submitted and waited for (so
// every earlier frame is complete, as the frame contract asks), with growing lists that start at one entry
// per segment (this view asks ~1.1 per segment: the default start, 2, would hold it) or the worst-case lists.
std::vector<GrowthFrame> frames(const hp::vk::Context& ctx, bool grow, int count) {
  hp::render::OffscreenRenderer target(ctx, hp::test::kSmallWidth, hp::test::kSmallHeight, 1, hp::RasterMode::Compute);
  hp::Renderer renderer(ctx, listSettings(target, grow));
  auto hair = renderer.createInstance(hp::test::defaultHeadWithStrands(3000), {});
  hp::HairInstance* one[] = {hair.get()};
  target.attach(renderer, one);
  std::vector<GrowthFrame> out;
  for (int f = 0; f < count; ++f) {
    hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      renderer.recordUpdate(cmd, std::uint64_t(f), one);
      renderer.recordShadows(cmd, std::uint64_t(f), hp::LightSpec{}, one);
      target.record(cmd, renderer, std::uint64_t(f), hp::test::smallFrontView(1.6f), one, 1.0f);
    }, "list growth frame");
    out.push_back({renderer.rasterStats(), target.readDisplay(), renderer.rasterCoverage()});
  }
  return out;
}
}  // namespace

TEST_F(VulkanTest, GrowingTileListsGrowOnceAFrameAsksForMoreAndThenDrawAsTheWorstCaseListsDo) {
  constexpr int kFrames = 4;  // framesInFlight 2: frame 0's slot comes round at frame 2
  const std::vector<GrowthFrame> grown = frames(*ctx, true, kFrames);
  const std::vector<GrowthFrame> worst = frames(*ctx, false, kFrames);
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
  // A frame whose lists were full cut every tile's farthest bins alike: each row of tiles keeps nearly all of
  // its coverage (the cut hair is mostly behind nearer hair). Cutting the entries past the capacity instead,
  // the last tiles in row order lost all theirs: the lowest rows with hair went bare (ratio 0 there).
  const std::vector<double> full = bandCoverage(grown[0].coverage), reserved = bandCoverage(worst[0].coverage);
  double lowest = 1.0;
  for (std::size_t band = 0; band < full.size(); ++band)
    if (reserved[band] > 1.0) lowest = std::min(lowest, full[band] / reserved[band]);
  // And no tile with hair went bare (the last tiles did, before). Each keeps at least its nearest entry, so a
  // sparse tile's only strand stays too: this view's 18 tiles with hair are all dense, so that part of the rule
  // is tested on the CPU (RasterLists.AFullListsShareKeepsEveryTileAnEntryAndFitsTheCapacity).
  std::size_t bareTiles = 0, hairTiles = 0;
  for (std::uint32_t ty = 0; ty < hp::test::kSmallHeight / 8; ++ty)
    for (std::uint32_t tx = 0; tx < hp::test::kSmallWidth / 8; ++tx) {
      double fullSum = 0.0, reservedSum = 0.0;
      for (std::uint32_t y = ty * 8; y < ty * 8 + 8; ++y)
        for (std::uint32_t x = tx * 8; x < tx * 8 + 8; ++x) {
          fullSum += grown[0].coverage[std::size_t(y) * hp::test::kSmallWidth + x];
          reservedSum += worst[0].coverage[std::size_t(y) * hp::test::kSmallWidth + x];
        }
      hairTiles += reservedSum > 0.0;
      bareTiles += reservedSum > 0.0 && fullSum == 0.0;
    }
  std::cout << "full lists: the lowest share of a tile row's coverage kept " << lowest << "; " << bareTiles << " of "
            << hairTiles << " tiles with hair went bare\n";
  EXPECT_GT(lowest, 0.9);
  EXPECT_EQ(bareTiles, 0u);
  // The images: a grown frame is the worst-case lists' within the compute raster's run-to-run noise (segments
  // of one depth bin composite in their atomics' order; 0 pixels here on lavapipe). A frame that dropped
  // entries differs by more (31 pixels).
  const std::size_t pixels = grown.back().display.size() / 4;
  const std::size_t droppedApart = pixelsApart(grown[0].display, worst[0].display, 1);
  const std::size_t grownApart = pixelsApart(grown.back().display, worst.back().display, 1);
  std::cout << "pixels apart from the worst-case lists' frame: " << droppedApart << " while dropping, " << grownApart
            << " once grown, of " << pixels << "\n";
  EXPECT_LE(grownApart, pixels / 50);
}

// The same with two frames really in flight (each submitted before the one two earlier is waited for), under
// synchronization validation: the lists grow while frames run, each slot takes the new ones when its own last
// frame is done, and the old ones go only then; the last frame, read once all are done, asks for no more than
// the grown lists hold and is the worst-case lists' frame within the compute raster's noise.
TEST_F(VulkanTest, GrowingTileListsGrowWithFramesInFlight) {
  hp::render::OffscreenRenderer target(*ctx, hp::test::kSmallWidth, hp::test::kSmallHeight, 1, hp::RasterMode::Compute);
  hp::Renderer renderer(*ctx, listSettings(target, true));
  auto hair = renderer.createInstance(hp::test::defaultHeadWithStrands(3000), {});
  hp::HairInstance* one[] = {hair.get()};
  target.attach(renderer, one);
  std::uint32_t start = 0;
  {
    hp::test::FrameSlots slots(*ctx, 2);
    for (std::uint64_t frame = 0; frame < 6; ++frame) {
      VkCommandBuffer cmd = slots.begin(frame % 2);  // waits for frame - 2
      renderer.recordUpdate(cmd, frame, one);
      renderer.recordShadows(cmd, frame, hp::LightSpec{}, one);
      target.record(cmd, renderer, frame, hp::test::smallFrontView(1.6f), one, 1.0f);
      slots.submit(frame % 2);
      if (frame == 0) {
        slots.wait(0);
        start = renderer.rasterStats().listCapacity;
      }
    }
  }  // every frame waited for
  const hp::compute::RasterStats last = renderer.rasterStats();
  const std::vector<std::uint8_t> image = target.readDisplay();
  const std::vector<GrowthFrame> worst = frames(*ctx, false, 6);  // its frame 5: the hair as simulated as far
  std::cout << "in flight: capacity " << start << " -> " << last.listCapacity << ", the last frame asked "
            << last.kept + last.droppedByCapacity << " and dropped " << last.droppedByCapacity << "; "
            << pixelsApart(image, worst.back().display, 1) << " pixels apart from the worst-case lists' frame\n";
  EXPECT_GT(last.listCapacity, start);
  EXPECT_EQ(last.droppedByCapacity, 0u);
  EXPECT_LE(pixelsApart(image, worst.back().display, 1), image.size() / 4 / 50);
}

// A target the Renderer rebuilds (here: the instance's strands set again) starts its lists at the size per
// segment its predecessor's had grown to, so the frames after the rebuild do not run with full lists again.
TEST_F(VulkanTest, ARebuiltTargetStartsItsListsWhereThePreviousOnesHadGrown) {
  hp::render::OffscreenRenderer target(*ctx, hp::test::kSmallWidth, hp::test::kSmallHeight, 1, hp::RasterMode::Compute);
  hp::Renderer renderer(*ctx, listSettings(target, true));
  const hp::HairAsset asset = hp::test::defaultHeadWithStrands(3000);
  auto hair = renderer.createInstance(asset, {});
  hp::HairInstance* one[] = {hair.get()};
  target.attach(renderer, one);
  std::uint64_t frame = 0;
  const auto draw = [&] {
    hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
      renderer.recordUpdate(cmd, frame, one);
      renderer.recordShadows(cmd, frame, hp::LightSpec{}, one);
      target.record(cmd, renderer, frame, hp::test::smallFrontView(1.6f), one, 1.0f);
    }, "rebuilt target frame");
    ++frame;
    return renderer.rasterStats();
  };
  const std::uint32_t start = draw().listCapacity;
  draw();
  const std::uint32_t grown = draw().listCapacity;  // frame 2: frame 0's slot again
  hair->setStrands(asset.topology, hair->settings().strands);  // the target is rebuilt for the new buffers
  const hp::compute::RasterStats rebuilt = draw();
  std::cout << "lists: start " << start << ", grown " << grown << ", the rebuilt target's first frame " << rebuilt.listCapacity
            << " (dropped " << rebuilt.droppedByCapacity << ")\n";
  EXPECT_GT(grown, start);
  EXPECT_GE(rebuilt.listCapacity, grown);
  EXPECT_EQ(rebuilt.droppedByCapacity, 0u);
}

// Frames of the small frame's head at three times its size (480x288, the same aspect) at the given camera
// distances, each waited for, with growing lists that shrink after `shrinkFrames` quiet frames or with the
// worst-case lists; each frame's device memory in use beside its statistics.
std::vector<std::pair<GrowthFrame, std::uint64_t>> framesAt(const hp::vk::Context& ctx, bool grow,
                                                            std::uint32_t shrinkFrames,
                                                            const std::vector<float>& distances) {
  constexpr std::uint32_t kWidth = 3 * hp::test::kSmallWidth, kHeight = 3 * hp::test::kSmallHeight;
  hp::render::OffscreenRenderer target(ctx, kWidth, kHeight, 1, hp::RasterMode::Compute);
  hp::RendererSettings settings = listSettings(target, grow);
  settings.rasterSettings.listShrinkFrames = shrinkFrames;
  settings.rasterSettings.tileBudget = 8192;  // the far head's 4 tiles need at most 32,768 entries
  hp::Renderer renderer(ctx, settings);
  auto hair = renderer.createInstance(hp::test::defaultHeadWithStrands(3000), {});
  hp::HairInstance* one[] = {hair.get()};
  target.attach(renderer, one);
  std::vector<std::pair<GrowthFrame, std::uint64_t>> out;
  for (std::size_t f = 0; f < distances.size(); ++f) {
    hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      renderer.recordUpdate(cmd, f, one);
      renderer.recordShadows(cmd, f, hp::LightSpec{}, one);
      hp::View view = hp::test::smallFrontView(distances[f]);
      view.extent = {kWidth, kHeight};
      target.record(cmd, renderer, f, view, one, 1.0f);
    }, "list shrink frame");
    out.push_back({{renderer.rasterStats(), target.readDisplay(), {}}, ctx.allocatedBytes()});
  }
  return out;
}

// Lists grown for a near view shrink back once the view has needed under a quarter of them for
// listShrinkFrames frames in a row (compute/raster/list_sizing.h) and free their memory; the frames after
// that draw from the smaller lists without dropping an entry, as the worst-case lists draw them.
TEST_F(VulkanTest, GrownTileListsShrinkBackAfterQuietFramesAndFreeTheirMemory) {
  // Frames 0-4 near (the lists grow at frame 2); 5-11 far, where the head covers 4 tiles and their tile
  // budget bounds the need. A slot's need is its last frame's: frames 5-7 are read as quiet at frames 7-9, so
  // frame 9's slot takes new lists, frame 10's too, and then no slot binds the old ones.
  std::vector<float> distances(5, 0.6f);
  distances.resize(12, 60.0f);
  const auto grown = framesAt(*ctx, true, 3, distances);
  const auto worst = framesAt(*ctx, false, 3, distances);
  const hp::compute::RasterStats& near = grown[4].first.stats;
  std::cout << "near lists " << near.listCapacity << " (asked " << near.kept + near.droppedByCapacity
            << "); far frames' capacity, device memory:";
  for (std::size_t f = 5; f < grown.size(); ++f)
    std::cout << " " << grown[f].first.stats.listCapacity << " (" << grown[f].second / 1024 << " KiB)";
  std::cout << "; the last frame asked " << grown.back().first.stats.kept + grown.back().first.stats.droppedByCapacity
            << "\n";
  EXPECT_EQ(near.droppedByCapacity, 0u);
  EXPECT_GT(near.listCapacity, grown[0].first.stats.listCapacity);  // grown for the near view
  EXPECT_EQ(grown[8].first.stats.listCapacity, near.listCapacity);   // two quiet frames read: not yet
  // Back to the lists' floor (one entry per segment and 16 per tile: the shrink's twice-the-need is less).
  const std::uint32_t shrunk = grown.back().first.stats.listCapacity;
  EXPECT_EQ(grown[9].first.stats.listCapacity, shrunk);
  EXPECT_LT(shrunk * 4ull, near.listCapacity * 3ull);
  // The old lists' memory is gone once both slots bind the new ones.
  const std::uint64_t freed = grown[4].second - std::min(grown[4].second, grown.back().second);
  EXPECT_GE(freed, (std::uint64_t(near.listCapacity) - shrunk) * 8 * 9 / 10);
  for (std::size_t f = 5; f < grown.size(); ++f) {
    EXPECT_EQ(grown[f].first.stats.droppedByCapacity, 0u) << "frame " << f;
    EXPECT_LE(pixelsApart(grown[f].first.display, worst[f].first.display, 1), grown[f].first.display.size() / 4 / 50)
        << "frame " << f;
  }
}
