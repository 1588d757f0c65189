// The head as an occluder through its depth shadow map (compute/shadows/shadow_maps.h, head_shadow_view.h): no banding
// on the skin. Metric: the mean vertical luminance step over skin pixels that a CPU ray cast of the
// head's field finds clearly lit (head_light_reference.h: no true cast-shadow edge or terminator near),
// against the same pixels of the same frame without shadows: with the head's own shadows, and with the
// hair's shadows on the skin too, within 1.3x. True shadow edges of the head (nose, ears, jaw) are
// excluded by that independent ray cast, so what is left is banding. The old path through the opacity
// slices (headOpacity > 0) must fail the same bound.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "samples/tools/render_job.h"
#include "tests/render/head_light_reference.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
// A still of the rest pose from orbit angle orbitDeg (0: the front), with the wrap term at 0.5: it lights the
// skin at grazing angles to the light and past the terminator, where the bands and rings showed (at the
// default wrap 0 that skin is dark: the banding test measured 1.00x and 1.05x, and the old path 1.21x,
// which no longer fails the bound, so these tests keep the wrap).
RenderRequest stillRequest(bool shadows, float orbitDeg = 0.0f) {
  RenderRequest r;
  r.look.wrap = 0.5f;
  r.scene.render = {240, 180, 4};
  r.scene.camera.orbitDeg = orbitDeg;
  r.scene.density.totalStrands = 3000;
  r.settleFrames = 0;  // the rest pose: this is about the head, not the hair's shape
  r.opacity.enabled = shadows;
  return r;
}

double luminance(const RenderResult& img, std::size_t pixel) {
  const std::uint8_t* p = &img.rgba[4 * pixel];
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// Skin: not background (the corner's colour) and unchanged when only the hair's absorption changes.
std::vector<bool> skinMask(const RenderResult& a, const RenderResult& otherHair) {
  std::vector<bool> skin(a.width * a.height);
  for (std::size_t p = 0; p < skin.size(); ++p) {
    bool hair = false, background = true;
    for (int c = 0; c < 3; ++c) {
      hair |= a.rgba[4 * p + c] != otherHair.rgba[4 * p + c];
      background &= a.rgba[4 * p + c] == a.rgba[c];
    }
    skin[p] = !hair && !background;
  }
  return skin;
}

// The frame without shadows and its skin pixels (skinMask against the same frame with blonde hair).
struct UnshadowedSkin {
  RenderResult frame;
  std::vector<bool> skin;
};
UnshadowedSkin unshadowedSkin(const vk::Context& ctx, const HairAsset& asset, const RenderRequest& unshadowed) {
  RenderRequest blonde = unshadowed;
  blonde.scene.material.absorption = {0.08, 0.15, 0.35};
  UnshadowedSkin s{renderStill(ctx, asset, unshadowed), {}};
  s.skin = skinMask(s.frame, renderStill(ctx, asset, blonde));
  return s;
}

// Mean |Y(x, y+1) - Y(x, y)| over vertically adjacent measured pixels.
double verticalStep(const RenderResult& img, const std::vector<bool>& skin) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::uint32_t y = 0; y + 1 < img.height; ++y)
    for (std::uint32_t x = 0; x < img.width; ++x) {
      const std::size_t p = std::size_t(y) * img.width + x, q = p + img.width;
      if (!skin[p] || !skin[q]) continue;
      sum += std::abs(luminance(img, q) - luminance(img, p));
      ++n;
    }
  return n ? sum / double(n) : 0.0;
}
}  // namespace

TEST_F(VulkanTest, HeadSkinShowsNoShadowBanding) {
  const RenderRequest on = stillRequest(true);
  const HairAsset asset = buildSceneAsset(on.scene);
  ASSERT_TRUE(asset.sdf);
  UnshadowedSkin unshadowed = unshadowedSkin(*ctx, asset, stillRequest(false));
  const RenderResult& off = unshadowed.frame;
  std::vector<bool>& measured = unshadowed.skin;
  const test::HeadLightMap cpu =
      test::traceHeadLight(*asset.sdf, on.scene.camera, on.scene.lights.front(), off.width, off.height);
  std::size_t skinPixels = 0, seenByCpu = 0, clearLit = 0;
  for (std::size_t p = 0; p < measured.size(); ++p) {
    if (!measured[p]) continue;
    ++skinPixels;
    seenByCpu += cpu.hit[p];
    measured[p] = cpu.clearLit[p];
    clearLit += measured[p];
  }
  // The ray cast frames the same head as the renderer (a flipped or shifted camera would miss here).
  ASSERT_GT(skinPixels, 2000u);
  ASSERT_GE(double(seenByCpu), 0.98 * double(skinPixels));
  ASSERT_GT(clearLit, 1000u);
  const double stepOff = verticalStep(off, measured);
  const double stepOn = verticalStep(renderStill(*ctx, asset, on), measured);
  RenderRequest headOnly = stillRequest(true);
  headOnly.opacity.k = 0.0f;  // hair shadows off (T = exp(0)), the head's depth map on
  const double stepHead = verticalStep(renderStill(*ctx, asset, headOnly), measured);
  RenderRequest slices = stillRequest(true);
  slices.opacity.headOpacity = 50.0f;  // the old path: the head in the opacity slices
  slices.opacity.deep = false;         // (global slices only: deep maps leave the head out of the slices)
  const double stepSlices = verticalStep(renderStill(*ctx, asset, slices), measured);
  std::cout << "mean vertical luminance step on clearly lit skin (" << clearLit << " of " << skinPixels
            << " skin px): no shadows " << stepOff << ", head depth map alone " << stepHead << " ("
            << stepHead / stepOff << "x), with hair shadows " << stepOn << " (" << stepOn / stepOff
            << "x), head in the opacity slices " << stepSlices << " (" << stepSlices / stepOff << "x)\n";
  // The head as its own occluder (the source of the bands): at most 1.3x the unshadowed step.
  EXPECT_LE(stepHead, 1.3 * stepOff);
  // With the hair's shadows on the skin too.
  EXPECT_LE(stepOn, 1.3 * stepOff);
  // The old path fails the same bound: the test can fail.
  EXPECT_GT(stepSlices, 1.3 * stepOff);
}

// The skin's far side from the light (seen from behind: the shoulders), where the wrap term still lights it:
// the depth map of back faces holds that skin itself, and the 3 x 3 taps beside a point seen at a slant read
// its own surface nearer the light, which drew concentric rings there until the receiver offset grew with
// the slope (head_shadow.glsl). Measured where a CPU ray cast finds the skin near the terminator and clear:
// N.L in [-0.2, 0) with nothing but its own body toward the light, or N.L in [0, 0.2) with the light
// reaching it (head_light_reference.h). The head's shadows may add at most 1.3x the unshadowed vertical step
// there.
TEST_F(VulkanTest, TheSkinsFarSideShowsNoSelfShadowRings) {
  auto request = [](bool shadows) {
    RenderRequest r = stillRequest(shadows, 180.0f);
    r.scene.render = {480, 360, 4};  // the far side is a thin band
    return r;
  };
  const RenderRequest on = request(true);
  const HairAsset asset = buildSceneAsset(on.scene);
  ASSERT_TRUE(asset.sdf);
  UnshadowedSkin unshadowed = unshadowedSkin(*ctx, asset, request(false));
  const RenderResult& off = unshadowed.frame;
  std::vector<bool>& measured = unshadowed.skin;
  test::HeadLightOptions wrapSide;
  wrapSide.minCosine = -0.2f;
  wrapSide.pastOwnBody = true;
  const LightSpec& light = on.scene.lights.front();
  const test::HeadLightMap far = test::traceHeadLight(*asset.sdf, on.scene.camera, light, off.width, off.height, wrapSide);
  const test::HeadLightMap near = test::traceHeadLight(*asset.sdf, on.scene.camera, light, off.width, off.height);
  std::size_t count = 0;
  for (std::size_t p = 0; p < measured.size(); ++p) {
    measured[p] = measured[p] && far.clearLit[p] && !near.clearLit[p];
    count += measured[p];
  }
  ASSERT_GT(count, 300u) << "too little skin on the far side to measure";
  RenderRequest headOnly = request(true);
  headOnly.opacity.k = 0.0f;  // hair shadows off (T = exp(0)), the head's depth map on
  const double stepOff = verticalStep(off, measured);
  const double stepHead = verticalStep(renderStill(*ctx, asset, headOnly), measured);
  std::cout << "mean vertical luminance step on the skin's far side (" << count << " px): no shadows " << stepOff
            << ", head depth map " << stepHead << " (" << stepHead / stepOff << "x)\n";
  EXPECT_LE(stepHead, 1.3 * stepOff);
}
