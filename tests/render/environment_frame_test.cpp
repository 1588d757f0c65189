// The real-time frame under the studio environment, the sun off, against the path-traced reference of the
// same export (docs/SHADING.md "Environment"): the default scene at 64x48 after 90 settling frames, the
// reference at 32 spp and 8 bounces, over the real-time hair coverage. The environment's bright regions are
// drawn as shadowed lights and the rest through SH; the negative control draws all of it through SH (no
// lights), which the bounds must refuse.
#include <gtest/gtest.h>

#include <iostream>
#include <memory>

#include "engine/core/shading/environment_map.h"
#include "samples/tools/environment_request.h"
#include "samples/tools/frame_export.h"
#include "samples/tools/image_compare.h"
#include "samples/tools/reference/path_tracer.h"
#include "samples/tools/render_job.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
// The studio-lit default frame with `lights` environment lights against `reference`, or, when that is null,
// against the reference traced here of its own export (kept in *traced).
ImageComparison studioFrame(const vk::Context& ctx, const HairAsset& asset, std::uint32_t lights,
                            const reference::TraceResult* reference, reference::TraceResult* traced) {
  RenderRequest request;
  request.scene.render.width = 64;
  request.scene.render.height = 48;
  request.settleFrames = 90;
  request.captureFrame = true;
  request.scene.lights[0].intensity = 0.0f;  // the sun off: the environment alone
  setEnvironment(request, std::make_shared<const EnvironmentMap>(studioEnvironment()), lights);
  const RenderResult result = renderStill(ctx, asset, request);
  EXPECT_TRUE(result.frame);
  if (!result.frame) return {};
  if (!reference) {
    const ExportedFrame frame = makeExportedFrame(request, asset, *result.frame, "physical");
    *traced = reference::traceReference(frame, {32, 8, 1, 0, nullptr});
    reference = traced;
  }
  return compareImages(result.frame->linear, reference->radiance, result.frame->hairAlpha, 1.0f);
}
}  // namespace

// Measured on lavapipe over reference seeds 1-3: with 2 lights 31.3-31.6 dB, luminance 1.05-1.09 (seed 1: 1.016
// since the far side's sky follows the head's depth, docs/SHADING.md "Ambient"), red/blue
// 0.96-1.08 of the reference's (whose own red/blue spreads 1.96-2.20 at 32 spp); with the SH alone luminance
// 1.59-1.65, red/blue 1.33-1.50 of it. Bounds: the light issue's 10% in luminance and 29 dB, the hue within
// 15% (the reference's spread); the SH-only frame must fail the first two.
TEST_F(VulkanTest, StudioEnvironmentLightsTheHairLikeTheReference) {
  RenderRequest scene;
  const HairAsset asset = buildSceneAsset(scene.scene);
  reference::TraceResult reference;
  const ImageComparison lit = studioFrame(*ctx, asset, 2, nullptr, &reference);
  const ImageComparison shOnly = studioFrame(*ctx, asset, 0, &reference, nullptr);
  for (const auto& [name, c] : {std::pair{"2 lights", lit}, std::pair{"SH only", shOnly}})
    std::cout << "studio, " << name << ": " << c.psnrDb << " dB, luminance " << c.luminanceRatio << ", red/blue "
              << c.redBlueImage << " vs " << c.redBlueReference << ", " << c.pixels << " hair pixels\n";
  EXPECT_GT(lit.pixels, 200u);
  EXPECT_GT(lit.psnrDb, 29.0);
  EXPECT_NEAR(lit.luminanceRatio, 1.0, 0.1);
  EXPECT_NEAR(lit.redBlueImage / lit.redBlueReference, 1.0, 0.15);
  EXPECT_GT(std::abs(shOnly.luminanceRatio - 1.0), 0.1) << "the negative control should fail the luminance bound";
  EXPECT_GT(std::abs(shOnly.redBlueImage / shOnly.redBlueReference - 1.0), 0.15) << "and the hue bound";
}
