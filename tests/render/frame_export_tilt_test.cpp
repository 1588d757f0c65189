// Each strand's cuticle tilt offset (HairMaterial::tiltVariation; shaders/shared/strands.h strandTilt) reaches
// the frame export as the real-time shading took it, and back: the reference shades strand s with
// ExportedFrame::strandMaterial(s), alpha_R plus that offset.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "samples/tools/frame_export.h"
#include "samples/tools/render_job.h"
#include "shaders/shared/strands.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
// The default scene (physical fibres) at 64x48 after 2 settling frames, with a tilt variation of 4 degrees.
RenderRequest tiltedFrame(LutMode mode) {
  RenderRequest request;
  request.scene.render.width = 64;
  request.scene.render.height = 48;
  request.scene.material.tiltVariation = glm::radians(4.0);
  request.lutMode = mode;
  request.settleFrames = 2;
  request.captureFrame = true;
  return request;
}

// Rewrites /fibre/strand_tilts_rad of DIR/frame.json with `edit` and expects the export to be refused with a
// message holding `expected`.
template <class Edit>
void expectRefusedAfter(const std::filesystem::path& dir, Edit edit, const std::string& expected) {
  nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "frame.json"));
  edit(j["fibre"]["strand_tilts_rad"]);
  std::ofstream(dir / "frame.json") << j.dump();
  try {
    readFrameExport(dir);
    ADD_FAILURE() << "accepted a frame.json whose tilts should fail with: " << expected;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}
}  // namespace

TEST_F(VulkanTest, FrameExportCarriesEachStrandsTiltAsTheShadingTookIt) {
  const RenderRequest request = tiltedFrame(LutMode::Physical);
  const HairAsset asset = buildSceneAsset(request.scene);
  const RenderResult result = renderStill(*ctx, asset, request);
  ASSERT_TRUE(result.frame);
  const FrameCapture& capture = *result.frame;
  const ExportedFrame frame = makeExportedFrame(request, asset, capture, "physical");
  const float variation = float(request.scene.material.tiltVariation);
  ASSERT_EQ(frame.strandTilts.size(), frame.strands.strandCount);
  double sumAbs = 0.0;
  for (std::uint32_t s = 0; s < frame.strands.strandCount; ++s) {
    const float t = frame.strandTilts[s];
    ASSERT_EQ(t, gpu::strandTilt(capture.strands.attributes[s].random, variation)) << "strand " << s;
    ASSERT_LE(std::abs(t), variation);
    EXPECT_EQ(frame.strandMaterial(s).alphaR, frame.material.alphaR + double(t));
    sumAbs += std::abs(t);
  }
  // Uniform over [-variation, variation): the mean magnitude is half of it, and both ends are reached.
  const auto [lo, hi] = std::minmax_element(frame.strandTilts.begin(), frame.strandTilts.end());
  EXPECT_NEAR(sumAbs / frame.strands.strandCount, 0.5 * variation, 0.03 * variation);
  EXPECT_LT(*lo, -0.95f * variation);
  EXPECT_GT(*hi, 0.95f * variation);

  const auto dir = std::filesystem::temp_directory_path() / "hairpipe_frame_export_tilt_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  writeFrameExport(dir, frame);
  EXPECT_EQ(readFrameExport(dir).strandTilts, frame.strandTilts);
  EXPECT_EQ(readFrameExport(dir).material.tiltVariation, frame.material.tiltVariation);
  expectRefusedAfter(dir, [&](nlohmann::json& t) { t[0] = 1.5 * variation; }, "strand_tilts_rad");
  writeFrameExport(dir, frame);
  expectRefusedAfter(dir, [](nlohmann::json& t) { t.erase(t.size() - 1); }, "tilts for");
  std::filesystem::remove_all(dir);

  // The float tables are of one tilt: the shading took none, so the export carries none.
  const RenderRequest flt = tiltedFrame(LutMode::Float);
  const RenderResult floatResult = renderStill(*ctx, asset, flt);
  ASSERT_TRUE(floatResult.frame);
  EXPECT_TRUE(makeExportedFrame(flt, asset, *floatResult.frame, "marschner").strandTilts.empty());
}

namespace {
// The mean |a - b| over every channel of two frames' linear images, relative to a's mean.
double relativeChange(const RenderResult& a, const RenderResult& b) {
  const auto& x = a.frame->linear.values;
  const auto& y = b.frame->linear.values;
  double diff = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    diff += std::abs(double(x[i]) - double(y[i]));
    sum += std::abs(double(x[i]));
  }
  return diff / sum;
}
}  // namespace

// The device shading takes each strand's tilt (MarschnerParams.caustic.z, strandTilt from the strand's random
// value: the graphics raster's vertex-to-fragment varying, the compute raster's shade pass): the same frame
// with and without the variation differs. The graphics raster is deterministic: its two renders of one setting
// are identical, so any change is the tilt's. The compute raster's compositing order within a depth bin
// follows its atomics, so two of its renders differ a little (1.3-1.7e-6 of the frame alone, ~1e-4 with
// the CPUs loaded); its change must be of the graphics raster's size. Measured on lavapipe (of the whole
// frame's radiance, which the skin dominates): graphics 1.7e-4 against 0, compute 2.5-3.0e-4; with the shade
// pass's tilt cut, compute read 4.2e-5 and failed.
TEST_F(VulkanTest, EachStrandsTiltReachesTheShadingOfBothRasters) {
  double graphicsChange = 0.0;
  for (RasterMode raster : {RasterMode::Graphics, RasterMode::Compute}) {
    RenderRequest tilted = tiltedFrame(LutMode::Physical);
    tilted.scene.render.width = 128;
    tilted.scene.render.height = 96;
    tilted.scene.density.totalStrands = 2000;
    tilted.scene.render.raster = raster;
    // What varies between two compute renders is left out as far as it can be: list drops (which entries go
    // depends on atomics' order), the opacity maps' splats and the skin's bounce.
    tilted.rasterSettings.tileBudget = 1u << 20;
    tilted.opacity.enabled = false;
    tilted.look.skinBounce = false;
    tilted.scene.render.msaa = 1;  // lavapipe draws 4-sample ribbons 5x slower; each frame is compared with its own kind
    RenderRequest straight = tilted;
    straight.scene.material.tiltVariation = 0.0;
    const HairAsset asset = buildSceneAsset(tilted.scene);
    const RenderResult a = renderStill(*ctx, asset, tilted), b = renderStill(*ctx, asset, tilted),
                       c = renderStill(*ctx, asset, straight);
    ASSERT_TRUE(a.frame && b.frame && c.frame);
    const double same = relativeChange(a, b), change = relativeChange(a, c);
    std::cout << rasterModeName(raster) << ": tilt 4 deg against none: mean change " << change
              << " of the frame's radiance (two renders: " << same << ")\n";
    if (raster == RasterMode::Graphics) {
      EXPECT_EQ(same, 0.0);
      EXPECT_GT(change, 2e-5);
      graphicsChange = change;
    } else {
      EXPECT_GT(change, 0.5 * graphicsChange);
    }
  }
}
