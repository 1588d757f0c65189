// The compute rasterizer on the default head: it agrees with the graphics path (hair mask IoU >= 0.9,
// mean hair colour within 10%), a forced-small tile budget reports its overflow and still draws hair,
// and the default budget loses nothing at 3840x2160 (binning only, to stay cheap).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "compute/strands/interpolate_pass.h"
#include "samples/tools/strand_dump.h"
#include "compute/strands/tessellate_pass.h"
#include "engine/core/hair/default_head.h"
#include "samples/tools/render_job.h"
#include "engine/vk/submit.h"
#include "tests/render/raster_rig.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
RenderRequest headRequest(RasterMode raster) {
  RenderRequest r;
  r.scene.render = {160, 120, 4, raster};
  r.scene.camera.orbitDeg = 145.0f;
  r.scene.density.totalStrands = 6000;
  r.settleFrames = 20;
  // From behind the hair is in shadow: the mask below finds it through the ambient term, which on dense
  // hair is the sky albedo x 0.15 of the sky (shaders/hair_shading.glsl), so the sky is made brighter.
  // The skin gets the hair's sky visibility too (the skin under the hair sees the sky through it; the
  // head shader does not model that yet): with the unoccluded skin 4-10x brighter than the hair's
  // ambient, the two rasters' different coverage of the skin between strands (analytic against MSAA)
  // decided the mean colour (compute 13% brighter at ambient 0.2), not the hair both draw.
  r.look.ambient = 0.4f;
  r.look.skinBounce = false;  // the compute raster alone adds it: the two rasters are compared, not the lighting
  r.look.farSideFromDepth = false;  // likewise: the graphics raster cannot read the head's depth
  r.look.skinColor *= hp::gpu::RENDER_HAIR_SKY_VISIBILITY;
  return r;
}

// Pixels where the hair shows: they change with the hair's absorption (the head's skin does not; the
// hair-coloured scalp does, in both paths alike).
std::vector<bool> hairMask(const RenderResult& dark, const RenderResult& blonde) {
  std::vector<bool> mask(dark.rgba.size() / 4, false);
  for (std::size_t p = 0; p < mask.size(); ++p)
    for (int c = 0; c < 3; ++c)
      if (std::abs(int(dark.rgba[4 * p + c]) - int(blonde.rgba[4 * p + c])) > 12) mask[p] = true;
  return mask;
}

struct Pair {
  RenderResult dark, blonde;
};

Pair renderPair(const vk::Context& ctx, const HairAsset& asset, RasterMode raster) {
  RenderRequest dark = headRequest(raster);
  RenderRequest blonde = dark;
  blonde.scene.material.absorption = {0.08, 0.15, 0.35};
  return {renderStill(ctx, asset, dark), renderStill(ctx, asset, blonde)};
}

glm::dvec3 meanColour(const RenderResult& image, const std::vector<bool>& mask) {
  glm::dvec3 sum(0.0);
  std::size_t n = 0;
  for (std::size_t p = 0; p < mask.size(); ++p)
    if (mask[p]) {
      sum += glm::dvec3(image.rgba[4 * p], image.rgba[4 * p + 1], image.rgba[4 * p + 2]);
      ++n;
    }
  return n ? sum / double(n) : sum;
}
}  // namespace

TEST_F(VulkanTest, ComputeAndGraphicsRastersAgreeOnTheDefaultHead) {
  const HairAsset asset = buildSceneAsset(headRequest(RasterMode::Compute).scene);
  const Pair compute = renderPair(*ctx, asset, RasterMode::Compute);
  const Pair graphics = renderPair(*ctx, asset, RasterMode::Graphics);
  ASSERT_EQ(compute.dark.raster, RasterMode::Compute);
  ASSERT_EQ(graphics.dark.raster, RasterMode::Graphics);
  const auto a = hairMask(compute.dark, compute.blonde);
  const auto b = hairMask(graphics.dark, graphics.blonde);
  std::size_t both = 0, either = 0;
  for (std::size_t p = 0; p < a.size(); ++p) {
    both += a[p] && b[p];
    either += a[p] || b[p];
  }
  const double iou = double(both) / double(either);
  std::vector<bool> common(a.size());
  for (std::size_t p = 0; p < a.size(); ++p) common[p] = a[p] && b[p];
  const glm::dvec3 c = meanColour(compute.dark, common), g = meanColour(graphics.dark, common);
  std::cout << "hair mask IoU " << iou << " (" << either << " px); mean hair colour compute " << c.x << " " << c.y
            << " " << c.z << ", graphics " << g.x << " " << g.y << " " << g.z << "\n";
  EXPECT_GE(iou, 0.9);
  EXPECT_GT(either, a.size() / 10) << "the hair should cover a good part of the frame";
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(c[k], g[k], 0.1 * g[k]) << "channel " << k;
}

TEST_F(VulkanTest, ASmallTileBudgetReportsItsOverflowAndStillDrawsHair) {
  RenderRequest request = headRequest(RasterMode::Compute);
  request.settleFrames = 0;
  const HairAsset asset = buildSceneAsset(request.scene);
  const RenderResult full = renderStill(*ctx, asset, request);
  request.rasterSettings.tileBudget = 64;  // about one entry per pixel where ~1000 are asked for
  const RenderResult starved = renderStill(*ctx, asset, request);
  ASSERT_TRUE(full.rasterStats && starved.rasterStats);
  EXPECT_EQ(full.rasterStats->overflow(), 0u);
  EXPECT_EQ(starved.rasterStats->requested, full.rasterStats->requested);
  EXPECT_GT(starved.rasterStats->droppedByTileBudget, 0u);
  EXPECT_EQ(starved.rasterStats->kept + starved.rasterStats->droppedByTileBudget, starved.rasterStats->requested);
  // The nearest bins survive: the hair is still there, if thinner than with every entry.
  std::size_t changed = 0, drawn = 0;
  const RenderResult background = [&] {
    RenderRequest none = request;
    none.scene.density.totalStrands = 1;
    return renderStill(*ctx, buildSceneAsset(none.scene), none);
  }();
  for (std::size_t p = 0; p < full.rgba.size(); p += 4) {
    const bool hairFull = full.rgba[p] != background.rgba[p] || full.rgba[p + 2] != background.rgba[p + 2];
    const bool hairStarved = starved.rgba[p] != background.rgba[p] || starved.rgba[p + 2] != background.rgba[p + 2];
    drawn += hairFull;
    changed += hairFull && hairStarved;
  }
  std::cout << "budget 64: " << starved.rasterStats->droppedByTileBudget << " of " << starved.rasterStats->requested
            << " entries dropped; hair pixels " << changed << " of " << drawn << "\n";
  EXPECT_GT(double(changed), 0.5 * double(drawn)) << "the starved frame still shows most of the hair";
}

TEST_F(VulkanTest, TheDefaultTileBudgetKeepsEveryEntryAt3840x2160) {
  // Default head, density and groom (clumps gather strands into fewer tiles), its render strands as the frame
  // computes them (rest pose), binned only.
  const Scene scene;
  const HairAsset asset = buildSceneAsset(scene);
  compute::StrandBuffers strands(*ctx, asset.guides.guideCount(), asset.guides.particlesPerGuide, asset.topology,
                                 compute::StrandOptions{});
  vk::Buffer particles = compute::uploadGuideParticles(*ctx, asset.guides);
  compute::TessellatePass tessellate(*ctx, particles, strands);
  compute::InterpolatePass interpolate(*ctx, strands, nullptr, scene.groom);
  vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) { compute::recordStrandPasses(*ctx, cmd, tessellate, interpolate); },
                    "strands");
  const VkExtent2D extent{3840, 2160};
  const CameraMatrices camera = orbitCamera(scene.camera, float(extent.width) / float(extent.height));
  test::RasterRig rig(*ctx, strands, extent, camera, render::LookSettings{}, scene.lights.front());
  rig.run(1.0f, /*binOnly=*/true);
  const compute::RasterStats stats = rig.pass->readStats();
  std::cout << "3840x2160: " << stats.requested << " entries, capacity " << rig.pass->capacity() << "\n";
  EXPECT_GT(stats.requested, 1'000'000u);
  EXPECT_EQ(stats.overflow(), 0u);
  EXPECT_EQ(stats.kept, stats.requested);
}
