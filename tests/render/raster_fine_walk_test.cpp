// The fine raster's two walks of a tile's list (compute/raster/strand_raster_pass.h FineWalk): the direct
// one CPU devices run and the staged one GPUs run must draw the same frame, radiance, coverage and motion,
// on a multisampled and a single-sample head, with tiles cut by the image's edge. CI runs only lavapipe,
// whose Auto is Direct: this is where the staged walk is checked. Not bit for bit: the scatter pass lists
// the segments of one (tile, depth bin) in the order its atomics ran, and the order changes the overlap
// mask's share, so two direct frames already differ, on lavapipe by up to 0.005 in radiance, 0.036 in
// coverage and 0.1 px in motion at a pixel; their totals by under 0.005%. A staged walk that lost one entry
// in 64 moved the coverage's total by 0.2%, the motion's by 0.06%, and a pixel's motion by 0.28 px.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "samples/tools/render_job.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
RenderRequest walkRequest(std::uint32_t headSamples, compute::FineWalk walk) {
  RenderRequest r;
  r.scene.render = {157, 117, headSamples, RasterMode::Compute};  // neither side a multiple of the 8-pixel tile
  r.scene.camera.orbitDeg = 60.0f;
  r.scene.density.totalStrands = 6000;
  r.settleFrames = 1;
  r.motionVectors = true;  // the settling step's motion: the hair moves as it settles
  r.captureFrame = true;
  r.rasterSettings.fineWalk = walk;
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

TEST_F(VulkanTest, TheStagedAndDirectFineWalksDrawTheSameFrame) {
  for (std::uint32_t samples : {4u, 1u}) {
    const RenderRequest direct = walkRequest(samples, compute::FineWalk::Direct);
    const HairAsset asset = buildSceneAsset(direct.scene);
    const RenderResult a = renderStill(*ctx, asset, direct);
    const RenderResult again = renderStill(*ctx, asset, direct);
    const RenderResult b = renderStill(*ctx, asset, walkRequest(samples, compute::FineWalk::Staged));
    ASSERT_TRUE(a.frame && b.frame && again.frame);
    std::cout << samples << " head samples:\n";
    const auto check = [&](const char* what, const LinearImage FrameCapture::*image, double largest) {
      const LinearImage &x = a.frame.value().*image, &y = b.frame.value().*image;
      const double total = sum(x), change = std::abs(sum(y) - total) / total;
      const Difference d = difference(x, y), noise = difference(x, again.frame.value().*image);
      std::cout << "  " << what << ": total " << total << ", staged " << change * 100 << "% off; per pixel staged "
                << d << ", direct again " << noise << "\n";
      EXPECT_GT(total, 500.0) << what << ": the frame should show a good deal of moving hair";
      EXPECT_LE(change, 5e-4) << what;
      EXPECT_LE(d.largest, largest) << what;
    };
    check("radiance", &FrameCapture::linear, 0.05);
    check("coverage", &FrameCapture::hairAlpha, 0.1);
    check("motion", &FrameCapture::motion, 0.25);
  }
}

// Auto takes the direct walk on CPU devices only, and only where its texel views fit the device; asked for
// where they do not, the direct walk is refused by name rather than reading past a view.
TEST(FineWalkChoice, AutoFallsBackToStagedWhereTheTexelViewsDoNotFit) {
  using compute::FineWalk;
  EXPECT_FALSE(compute::chooseStagedWalk(FineWalk::Auto, /*cpuDevice=*/true, /*texelsFit=*/true));
  EXPECT_TRUE(compute::chooseStagedWalk(FineWalk::Auto, true, false));
  EXPECT_TRUE(compute::chooseStagedWalk(FineWalk::Auto, false, true));
  EXPECT_TRUE(compute::chooseStagedWalk(FineWalk::Staged, true, false));
  EXPECT_FALSE(compute::chooseStagedWalk(FineWalk::Direct, false, true));
  try {
    compute::chooseStagedWalk(FineWalk::Direct, true, false);
    ADD_FAILURE() << "the direct walk was taken without room for its texel views";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("maxTexelBufferElements"), std::string::npos) << e.what();
  }
}
