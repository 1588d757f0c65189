// The compute raster's shading spacing (compute::RasterSettings::shadingSpacing, shared/raster.h
// RASTER_COLOR_A_MID): where a strand's vertices 2j and 2j + 2 lie within the spacing on screen (and the pair
// turns little), vertex 2j + 1 is not shaded and the fine pass takes their mean for it. Checked on the default head: how many vertices the
// shade pass shades (at most 19 of a 36-vertex strand's when all of it is listed and short on screen, every listed one
// at spacing 0 or below every pair's length), and that the frame stays the frame. The staged walk reads the
// same flags: raster_fine_walk_test.cpp draws its frames at the default spacing.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "engine/core/error.h"
#include "engine/vk/transfer.h"
#include "samples/tools/image_compare.h"
#include "samples/tools/render_job.h"
#include "tests/render/raster_rig.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
RenderRequest spacingRequest(float spacing) {
  RenderRequest r;
  r.scene.render = {200, 150, 4, RasterMode::Compute};
  r.scene.density.totalStrands = 3000;
  r.settleFrames = 1;
  r.captureFrame = true;
  r.rasterSettings.shadingSpacing = spacing;
  return r;
}
}  // namespace

TEST_F(VulkanTest, TheShadingSpacingShadesEveryOtherVertexWhereStrandsAreShortOnScreen) {
  const RenderRequest every = spacingRequest(0.0f);
  const HairAsset asset = buildSceneAsset(every.scene);
  const RenderResult full = renderStill(*ctx, asset, every);
  const RenderResult tiny = renderStill(*ctx, asset, spacingRequest(1e-3f));  // below every pair's length
  const RenderResult wide = renderStill(*ctx, asset, spacingRequest(4096.0f));
  const RenderResult mixed = renderStill(*ctx, asset, spacingRequest(3.0f));  // about the median pair here
  const RenderResult defaults = renderStill(*ctx, asset, spacingRequest(compute::RasterSettings{}.shadingSpacing));
  ASSERT_TRUE(full.rasterStats && tiny.rasterStats && wide.rasterStats && mixed.rasterStats && defaults.rasterStats);
  ASSERT_TRUE(full.frame && tiny.frame && wide.frame && mixed.frame);
  ASSERT_EQ(full.verticesPerStrand, 36u);
  const double shaded = double(full.rasterStats->shaded);
  std::cout << "shaded vertices: every " << shaded << ", spacing 1e-3 " << tiny.rasterStats->shaded << ", 3 "
            << mixed.rasterStats->shaded << ", default " << defaults.rasterStats->shaded << ", 4096 "
            << wide.rasterStats->shaded << " of " << full.strands * full.verticesPerStrand << "\n";
  EXPECT_GT(shaded, 0.3 * full.strands * full.verticesPerStrand) << "the head's hair should mostly be in view";
  // Below every pair's length but a strand seen end-on, whose pair may be shorter still.
  EXPECT_LE(tiny.rasterStats->shaded, full.rasterStats->shaded);
  EXPECT_GE(double(tiny.rasterStats->shaded), shaded * 0.999);
  // A strand listed whole keeps its even vertices and its tip, 19 of 36 (0.53); one listed in part keeps at
  // least half of its listed vertices and at most all of them (a lone listed segment: 2 of 2), so the share
  // over the frame lies a little above 19/36 where most strands are listed whole.
  EXPECT_LE(double(wide.rasterStats->shaded), shaded * 0.56);
  EXPECT_GE(double(wide.rasterStats->shaded), shaded * 0.5);
  EXPECT_LT(mixed.rasterStats->shaded, full.rasterStats->shaded);
  EXPECT_GT(mixed.rasterStats->shaded, wide.rasterStats->shaded);
  EXPECT_LT(defaults.rasterStats->shaded, full.rasterStats->shaded);
  EXPECT_GE(defaults.rasterStats->shaded, wide.rasterStats->shaded);

  const LinearImage& mask = full.frame->hairAlpha;
  const ImageComparison same = compareImages(tiny.frame->linear, full.frame->linear, mask, 1.0f);
  const ImageComparison half = compareImages(wide.frame->linear, full.frame->linear, mask, 1.0f);
  const ImageComparison some = compareImages(mixed.frame->linear, full.frame->linear, mask, 1.0f);
  std::cout << "against every vertex shaded: spacing 1e-3 " << same.psnrDb << " dB, 3 " << some.psnrDb << " dB, 4096 "
            << half.psnrDb << " dB (luminance " << half.luminanceRatio << ") over " << half.pixels << " hair pixels\n";
  EXPECT_GT(same.psnrDb, 45.0) << "only the order of the scatter's atomics may differ";
  // The means stand in for the shaded middles: the frame moves little, and not darker or lighter overall.
  for (const ImageComparison& c : {half, some}) {
    EXPECT_GT(c.psnrDb, 38.0);
    EXPECT_NEAR(c.luminanceRatio, 1.0, 0.01);
  }
}

// Three strands of 5 vertices (pairs 0-1 and 2-3) across a 64 x 48 frame, each pair's ends 16 px apart: a
// straight one and two that zigzag, their odd vertices 1 px (1/16 of the chord) and 4 px (1/4) off it. At a
// spacing of 24 px the straight and the gentle one shade vertices 0, 2 and 4 only; the sharp one turns by
// ~53 degrees at each odd vertex and keeps all five.
TEST_F(VulkanTest, AShortPairThatTurnsSharplyOnScreenKeepsItsMiddleVertex) {
  constexpr VkExtent2D extent{64, 48};
  constexpr std::uint32_t q = 5;
  const CameraMatrices camera = test::rigCamera(extent, 0.8f);
  compute::StrandOptions options;
  options.verticesPerStrand = q;
  options.guidesOnly = true;
  compute::StrandBuffers strands(*ctx, 3, 2, InterpolationTopology{}, options);
  std::vector<glm::vec4> positions, tangents;
  std::vector<gpu::StrandAttributes> attributes;
  const float offsets[3] = {0.0f, 1.0f, 4.0f};
  for (std::uint32_t s = 0; s < 3; ++s) {
    for (std::uint32_t j = 0; j < q; ++j) {
      const float y = 10.0f + 14.0f * float(s) + ((j & 1u) != 0u ? offsets[s] : 0.0f);
      const glm::vec3 world = test::worldAtPixel(camera, extent, {8.0f + 8.0f * float(j), y}, 1.0f);
      positions.emplace_back(world, float(j) / float(q - 1));
      tangents.emplace_back(1.0f, 0.0f, 0.0f, 0.0f);
    }
    attributes.push_back({0.5f, 1.0f, 1.0f, s});
  }
  const auto& chunk = strands.chunks().front();
  vk::upload<glm::vec4>(*ctx, chunk.positions, positions, vk::BufferUse::ComputeRead);
  vk::upload<glm::vec4>(*ctx, chunk.tangents, tangents, vk::BufferUse::ComputeRead);
  vk::upload<gpu::StrandAttributes>(*ctx, chunk.attributes, attributes, vk::BufferUse::ComputeRead);
  render::LookSettings look;
  look.strandWidth = 2.0f * std::tan(0.5f * camera.fovY) / float(extent.height);  // one pixel at unit depth
  compute::RasterSettings settings;
  settings.shadingSpacing = 24.0f;
  test::RasterRig rig(*ctx, strands, extent, camera, look, LightSpec{}, settings);
  rig.run();
  EXPECT_EQ(rig.pass->readStats().shaded, 3u + 3u + 5u);
  settings.shadingSpacing = 0.0f;
  test::RasterRig every(*ctx, strands, extent, camera, look, LightSpec{}, settings);
  every.run();
  EXPECT_EQ(every.pass->readStats().shaded, 15u);
}

TEST(ShadingSpacing, IsCheckedByName) {
  for (float bad : {-1.0f, std::nanf(""), 5000.0f}) {
    compute::RasterSettings s;
    s.shadingSpacing = bad;
    try {
      s.validate();
      ADD_FAILURE() << "shadingSpacing " << bad << " was accepted";
    } catch (const hp::Error& e) {
      EXPECT_NE(std::string(e.what()).find("shadingSpacing"), std::string::npos) << e.what();
    }
  }
  compute::RasterSettings zero;
  zero.shadingSpacing = 0.0f;
  EXPECT_NO_THROW(zero.validate());
}
