// The compute raster with and without workgroup sharing (compute/raster/strand_raster_pass.h
// WorkgroupSharing: the fine pass's staged walk of a tile's list, the bin pass's grouped counting) must
// bin the same entries and draw the same frame, radiance, coverage and motion, on a multisampled and a
// single-sample head, with tiles cut by the image's edge. CI runs only lavapipe, whose Auto is Off: this is
// where the GPUs' passes are checked. Not bit for bit: the scatter pass lists
// the segments of one (tile, depth bin) in the order its atomics ran, and the order changes the overlap
// mask's share, so two direct frames already differ, on lavapipe by up to 0.005 in radiance, 0.036 in
// coverage and 0.1 px in motion at a pixel; their totals by under 0.005%. A staged walk that lost one entry
// in 64 moved the coverage's total by 0.2%, the motion's by 0.06%, and a pixel's motion by 0.28 px.
// The binned entries are counted exactly: the same requested, kept and dropped either way.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "engine/core/hair/default_head.h"
#include "samples/tools/render_job.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
RenderRequest sharingRequest(std::uint32_t headSamples, compute::WorkgroupSharing sharing) {
  RenderRequest r;
  r.scene.render = {157, 117, headSamples, RasterMode::Compute};  // neither side a multiple of the 8-pixel tile
  r.scene.camera.orbitDeg = 60.0f;
  r.scene.density.totalStrands = 6000;
  r.settleFrames = 1;
  r.motionVectors = true;  // the settling step's motion: the hair moves as it settles
  r.captureFrame = true;
  r.rasterSettings.sharing = sharing;
  return r;
}

struct Difference {
  double largest = 0.0;  // relative to max(1, |a|)
  double mean = 0.0;     // of the absolute differences
};

Difference difference(const LinearImage& a, const LinearImage& b) {
  EXPECT_EQ(a.values.size(), b.values.size());
  Difference d;
  const std::size_t n = std::min(a.values.size(), b.values.size());
  for (std::size_t i = 0; i < n; ++i) {
    const double delta = std::abs(double(a.values[i]) - b.values[i]);
    d.largest = std::max(d.largest, delta / std::max(1.0, std::abs(double(a.values[i]))));
    d.mean += delta / double(n);
  }
  return d;
}

std::ostream& operator<<(std::ostream& out, const Difference& d) {
  return out << d.largest << " (mean " << d.mean << ")";
}

double sum(const LinearImage& image) {
  double s = 0.0;
  for (float v : image.values) s += std::abs(v);
  return s;
}
}  // namespace

TEST_F(VulkanTest, TheRasterDrawsTheSameFrameWithAndWithoutWorkgroupSharing) {
  for (std::uint32_t samples : {4u, 1u}) {
    const RenderRequest direct = sharingRequest(samples, compute::WorkgroupSharing::Off);
    const HairAsset asset = buildSceneAsset(direct.scene);
    const RenderResult a = renderStill(*ctx, asset, direct);
    const RenderResult again = renderStill(*ctx, asset, direct);
    const RenderResult b = renderStill(*ctx, asset, sharingRequest(samples, compute::WorkgroupSharing::On));
    ASSERT_TRUE(a.frame && b.frame && again.frame && a.rasterStats && b.rasterStats);
    EXPECT_GT(a.rasterStats->requested, 0u);
    EXPECT_EQ(b.rasterStats->requested, a.rasterStats->requested);
    EXPECT_EQ(b.rasterStats->kept, a.rasterStats->kept);
    EXPECT_EQ(b.rasterStats->overflow(), a.rasterStats->overflow());
    std::cout << samples << " head samples:\n";
    const auto check = [&](const char* what, const LinearImage FrameCapture::*image, double largest) {
      const LinearImage &x = a.frame.value().*image, &y = b.frame.value().*image;
      const double total = sum(x), change = std::abs(sum(y) - total) / total;
      const Difference d = difference(x, y), noise = difference(x, again.frame.value().*image);
      std::cout << "  " << what << ": total " << total << ", shared " << change * 100 << "% off; per pixel shared "
                << d << ", alone again " << noise << "\n";
      EXPECT_GT(total, 500.0) << what << ": the frame should show a good deal of moving hair";
      EXPECT_LE(change, 5e-4) << what;
      EXPECT_LE(d.largest, largest) << what;
    };
    check("radiance", &FrameCapture::linear, 0.05);
    check("coverage", &FrameCapture::hairAlpha, 0.1);
    check("motion", &FrameCapture::motion, 0.25);
  }
}

// The grouped counting keeps each key's budget: with 64 entries a tile most are dropped, the same ones'
// count either way.
TEST_F(VulkanTest, WorkgroupSharingKeepsTheTileBudget) {
  RenderRequest off = sharingRequest(4, compute::WorkgroupSharing::Off);
  off.rasterSettings.tileBudget = 64;
  RenderRequest on = off;
  on.rasterSettings.sharing = compute::WorkgroupSharing::On;
  const HairAsset asset = buildSceneAsset(off.scene);
  const RenderResult a = renderStill(*ctx, asset, off), b = renderStill(*ctx, asset, on);
  ASSERT_TRUE(a.rasterStats && b.rasterStats);
  std::cout << "budget 64: requested " << a.rasterStats->requested << ", dropped " << a.rasterStats->droppedByTileBudget
            << " alone, " << b.rasterStats->droppedByTileBudget << " shared\n";
  EXPECT_GT(a.rasterStats->droppedByTileBudget, a.rasterStats->requested / 2);
  EXPECT_EQ(b.rasterStats->requested, a.rasterStats->requested);
  EXPECT_EQ(b.rasterStats->droppedByTileBudget, a.rasterStats->droppedByTileBudget);
  EXPECT_EQ(b.rasterStats->kept, a.rasterStats->kept);
}
