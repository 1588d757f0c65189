// Level of detail (InstanceSettings::lod): the fraction follows the view's distance, the drawn strands follow
// the fraction, and the widened half of the strands keeps the hair's coverage where half the strands at
// their own width do not. Compute raster (coverage is its alpha) and graphics ribbons.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "compute/renderer/renderer.h"
#include "compute/shadows/shadow_maps.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "samples/tools/offscreen_renderer.h"
#include "tests/support/small_frame.h"
#include "tests/support/vk_fixture.h"

using hp::test::VulkanTest;

namespace {
using hp::test::kSmallHeight;
using hp::test::kSmallWidth;

// Half the strands at the front view's distance (about 0.8 from the head's origin).
hairpipe::LodSettings halfAtTheView() {
  hairpipe::LodSettings lod;
  lod.enabled = true;
  lod.startDistance = 0.1f;
  lod.endDistance = 0.5f;
  lod.minFraction = 0.5f;
  return lod;
}

struct Coverage {
  double alpha = 0.0;                // sum of the hair image's alpha (compute raster)
  std::uint64_t segmentTiles = 0;    // (segment, tile) entries the drawn segments asked for
};

// One frame of `asset` on the compute raster; `lod` for the instance.
Coverage computeFrame(const hp::vk::Context& ctx, const hp::HairAsset& asset, const hairpipe::LodSettings& lod) {
  hp::render::OffscreenRenderer target(ctx, kSmallWidth, kSmallHeight, 1, hp::RasterMode::Compute);
  hp::RendererSettings settings;
  settings.formats = target.formats();
  settings.raster = hp::RasterMode::Compute;
  settings.opacity.resolution = 256;
  hp::Renderer renderer(ctx, settings);
  hp::InstanceSettings s;
  s.lod = lod;
  auto instance = renderer.createInstance(asset, s);
  hp::HairInstance* one[] = {instance.get()};
  target.attach(renderer, one);
  hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    renderer.recordUpdate(cmd, 0, one);
    renderer.recordShadows(cmd, 0, hp::LightSpec{}, one);
    target.record(cmd, renderer, 0, hp::test::smallFrontView(), one, 1.0f);
  }, "lod frame");
  const auto bytes = hp::vk::readbackImage(ctx, renderer.rasterImage(), hp::vk::ImageUse::FragmentSampled);
  const auto alpha = hp::render::rgbOfHalfRgba(bytes, {kSmallWidth, kSmallHeight}, 3, 1);
  Coverage c;
  for (float a : alpha.values) c.alpha += a;
  c.segmentTiles = renderer.rasterStats().requested;
  return c;
}

// Pixels of the graphics frame that differ from the background (the corner pixel).
std::size_t graphicsHairPixels(const hp::vk::Context& ctx, const hp::HairAsset& asset, const hairpipe::LodSettings& lod) {
  hp::render::OffscreenRenderer target(ctx, kSmallWidth, kSmallHeight, 1);
  hp::RendererSettings settings;
  settings.formats = target.formats();
  settings.opacity.resolution = 256;
  hp::Renderer renderer(ctx, settings);
  hp::InstanceSettings s;
  s.lod = lod;
  s.drawHead = false;  // the hair alone
  auto instance = renderer.createInstance(asset, s);
  hp::HairInstance* one[] = {instance.get()};
  hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    renderer.recordUpdate(cmd, 0, one);
    renderer.recordShadows(cmd, 0, hp::LightSpec{}, one);
    target.record(cmd, [&](VkCommandBuffer c) { renderer.recordDraw(c, 0, hp::test::smallFrontView(), one); }, 1.0f);
  }, "lod graphics frame");
  const std::vector<std::uint8_t> rgba = target.readDisplay();
  std::size_t n = 0;
  for (std::size_t px = 0; px < rgba.size(); px += 4)
    n += rgba[px] != rgba[0] || rgba[px + 1] != rgba[1] || rgba[px + 2] != rgba[2];
  return n;
}
}  // namespace

TEST(Lod, FractionFollowsDistanceAndCountsAtLeastOneStrand) {
  hairpipe::LodSettings lod;
  lod.startDistance = 2.0f;
  lod.endDistance = 6.0f;
  lod.minFraction = 0.2f;
  EXPECT_EQ(hp::lodFraction(lod, 10.0f), 1.0f);  // off
  lod.enabled = true;
  EXPECT_EQ(hp::lodFraction(lod, 1.0f), 1.0f);
  EXPECT_EQ(hp::lodFraction(lod, 2.0f), 1.0f);
  EXPECT_FLOAT_EQ(hp::lodFraction(lod, 4.0f), 0.6f);
  EXPECT_FLOAT_EQ(hp::lodFraction(lod, 6.0f), 0.2f);
  EXPECT_FLOAT_EQ(hp::lodFraction(lod, 60.0f), 0.2f);
  EXPECT_EQ(hp::lodStrandCount(0.5f, 20000), 10000u);
  EXPECT_EQ(hp::lodStrandCount(0.25f, 3), 1u);
  EXPECT_EQ(hp::lodStrandCount(1e-9f, 3), 1u);
  EXPECT_EQ(hp::lodStrandCount(1.0f, 3), 3u);
}

// The opacity maps' strands: the view's level of detail, capped at OpacitySettings::shadowStrands (0: no
// cap), never past it, widened by the fraction of all strands they stand for.
TEST(Lod, TheMapsDrawTheLevelOfDetailCappedAtTheirStrandBudget) {
  const auto same = [](hp::ShadowSample s, std::uint32_t drawn, float fraction) {
    EXPECT_EQ(s.drawn, drawn);
    EXPECT_FLOAT_EQ(s.fraction, fraction);
  };
  same(hp::shadowSample(1.0f, 1000000, 0), 1000000, 1.0f);
  same(hp::shadowSample(1.0f, 20000, 65536), 20000, 1.0f);
  same(hp::shadowSample(1.0f, 65536, 65536), 65536, 1.0f);
  same(hp::shadowSample(1.0f, 131072, 65536), 65536, 0.5f);
  same(hp::shadowSample(0.25f, 131072, 65536), 32768, 0.25f);  // the level of detail draws fewer
  for (std::uint32_t strands : {136320u, 136321u, 1000000u, 999999u, 70001u})
    EXPECT_EQ(hp::shadowSample(1.0f, strands, 65536).drawn, 65536u) << strands;  // the budget, not one past it
}

TEST_F(VulkanTest, HalfTheStrandsWidenedKeepTheHairsCoverageOnTheComputeRaster) {
  const hp::HairAsset full = hp::test::defaultHeadWithStrands(3000), halfAsset = hp::test::defaultHeadWithStrands(1500);
  const Coverage all = computeFrame(*ctx, full, {});
  const Coverage lod = computeFrame(*ctx, full, halfAtTheView());
  const Coverage thin = computeFrame(*ctx, halfAsset, {});  // half the strands, not widened
  std::cout << "coverage (sum of alpha): all " << all.alpha << ", LOD half widened " << lod.alpha
            << ", half at their own width " << thin.alpha << "; segment-tile entries " << all.segmentTiles << " / "
            << lod.segmentTiles << " / " << thin.segmentTiles << "\n";
  EXPECT_NEAR(lod.alpha / all.alpha, 1.0, 0.1);
  EXPECT_LT(thin.alpha / all.alpha, 0.9);  // what the widening makes up for
  // Half the segments are drawn: their tile entries fall with them (widened strands touch a few more tiles).
  EXPECT_LT(double(lod.segmentTiles), 0.65 * double(all.segmentTiles));
  EXPECT_GT(double(lod.segmentTiles), 0.4 * double(all.segmentTiles));
}

TEST_F(VulkanTest, HalfTheStrandsWidenedKeepTheHairsCoverageInGraphics) {
  const hp::HairAsset full = hp::test::defaultHeadWithStrands(3000), halfAsset = hp::test::defaultHeadWithStrands(1500);
  const std::size_t all = graphicsHairPixels(*ctx, full, {});
  const std::size_t lod = graphicsHairPixels(*ctx, full, halfAtTheView());
  const std::size_t thin = graphicsHairPixels(*ctx, halfAsset, {});
  std::cout << "hair pixels: all " << all << ", LOD half widened " << lod << ", half at their own width " << thin << "\n";
  EXPECT_NEAR(double(lod) / double(all), 1.0, 0.1);
}
