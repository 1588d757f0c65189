// Each strand's cuticle tilt offset and roughness scale (HairMaterial::tiltVariation, roughnessVariation;
// shaders/shared/strands.h strandTilt, strandRoughness) reach the device shading of both rasters and the frame
// export as the shading took them, and back: the reference shades strand s with ExportedFrame::strandMaterial(s),
// alpha_R plus that offset, beta_R times that scale.
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
#include "tests/support/cli_runner.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
// The default scene (physical fibres) at 64x48 after 2 settling frames, with a tilt variation of 4 degrees and
// the largest roughness variation, 25%.
RenderRequest variedFrame(LutMode mode) {
  RenderRequest request;
  request.scene.render.width = 64;
  request.scene.render.height = 48;
  request.scene.material.tiltVariation = glm::radians(4.0);
  request.scene.material.roughnessVariation = 0.25;
  request.lutMode = mode;
  request.settleFrames = 2;
  request.captureFrame = true;
  return request;
}

// Rewrites /fibre/`list` of DIR/frame.json with `edit` and expects the export to be refused with a message
// holding `expected`.
template <class Edit>
void expectRefusedAfter(const std::filesystem::path& dir, const char* list, Edit edit, const std::string& expected) {
  nlohmann::json j = nlohmann::json::parse(std::ifstream(dir / "frame.json"));
  edit(j["fibre"][list]);
  std::ofstream(dir / "frame.json") << j.dump();
  try {
    readFrameExport(dir);
    ADD_FAILURE() << "accepted a frame.json whose " << list << " should fail with: " << expected;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
  }
}
}  // namespace

TEST_F(VulkanTest, FrameExportCarriesEachStrandsTiltAndRoughnessAsTheShadingTookThem) {
  const RenderRequest request = variedFrame(LutMode::Physical);
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

  // Roughness scales: each of the levels evenly spaced over [1 - V, 1 + V], equally often.
  const float roughness = float(request.scene.material.roughnessVariation);
  ASSERT_EQ(frame.strandRoughness.size(), frame.strands.strandCount);
  std::vector<std::uint32_t> perLevel(gpu::STRAND_ROUGHNESS_LEVELS, 0);
  for (std::uint32_t s = 0; s < frame.strands.strandCount; ++s) {
    const float r = frame.strandRoughness[s];
    const std::uint32_t level = gpu::strandRoughnessLevel(capture.strands.attributes[s].random);
    ASSERT_EQ(r, gpu::strandRoughness(capture.strands.attributes[s].random, roughness)) << "strand " << s;
    ASSERT_EQ(r, gpu::strandRoughnessOfLevel(level, roughness)) << "strand " << s;
    EXPECT_EQ(frame.strandMaterial(s).betaR, frame.material.betaR * double(r));
    ++perLevel[level];
  }
  EXPECT_EQ(gpu::strandRoughnessOfLevel(0, roughness), 1.0f - roughness);
  EXPECT_EQ(gpu::strandRoughnessOfLevel(gpu::STRAND_ROUGHNESS_LEVELS - 1, roughness), 1.0f + roughness);
  const double expected = double(frame.strands.strandCount) / gpu::STRAND_ROUGHNESS_LEVELS;
  for (std::uint32_t n : perLevel) EXPECT_NEAR(double(n), expected, 0.15 * expected);

  const auto dir = test::freshTempPath("hairpipe_frame_export_variation_test");
  std::filesystem::create_directories(dir);
  writeFrameExport(dir, frame);
  const ExportedFrame back = readFrameExport(dir);
  EXPECT_EQ(back.strandTilts, frame.strandTilts);
  EXPECT_EQ(back.material.tiltVariation, frame.material.tiltVariation);
  EXPECT_EQ(back.strandRoughness, frame.strandRoughness);
  EXPECT_EQ(back.material.roughnessVariation, frame.material.roughnessVariation);
  expectRefusedAfter(dir, "strand_tilts_rad", [&](nlohmann::json& t) { t[0] = 1.5 * variation; }, "strand_tilts_rad");
  writeFrameExport(dir, frame);
  expectRefusedAfter(dir, "strand_tilts_rad", [](nlohmann::json& t) { t.erase(t.size() - 1); }, "tilts for");
  writeFrameExport(dir, frame);
  expectRefusedAfter(dir, "strand_roughness_scales", [&](nlohmann::json& t) { t[0] = 1.0 + 1.5 * roughness; },
                     "strand_roughness_scales");
  writeFrameExport(dir, frame);
  expectRefusedAfter(dir, "strand_roughness_scales", [](nlohmann::json& t) { t[0] = "rough"; },
                     "strand_roughness_scales");
  writeFrameExport(dir, frame);
  expectRefusedAfter(dir, "strand_roughness_scales", [](nlohmann::json& t) { t.erase(t.size() - 1); }, "scales for");
  std::filesystem::remove_all(dir);

  // The float tables are of one tilt and one roughness: the shading took neither, so the export carries neither.
  const RenderRequest flt = variedFrame(LutMode::Float);
  const RenderResult floatResult = renderStill(*ctx, asset, flt);
  ASSERT_TRUE(floatResult.frame);
  const ExportedFrame floatFrame = makeExportedFrame(flt, asset, *floatResult.frame, "marschner");
  EXPECT_TRUE(floatFrame.strandTilts.empty());
  EXPECT_TRUE(floatFrame.strandRoughness.empty());
}

namespace {
// The mean |a - b| over every channel of two frames' linear images, relative to a's mean, over the pixels `where`
// says (every pixel when it is empty).
double relativeChange(const RenderResult& a, const RenderResult& b, const std::vector<bool>& where = {}) {
  const auto& x = a.frame->linear.values;
  const auto& y = b.frame->linear.values;
  const std::size_t channels = x.size() / (a.frame->linear.width * a.frame->linear.height);
  double diff = 0.0, sum = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!where.empty() && !where[i / channels]) continue;
    diff += std::abs(double(x[i]) - double(y[i]));
    sum += std::abs(double(x[i]));
  }
  return sum > 0.0 ? diff / sum : 0.0;
}

// The pixels whose radiance differs by more than 2% between two frames of the deterministic graphics raster.
std::vector<bool> changedPixels(const RenderResult& a, const RenderResult& b) {
  const auto& x = a.frame->linear.values;
  const auto& y = b.frame->linear.values;
  const std::size_t pixels = std::size_t(a.frame->linear.width) * a.frame->linear.height, channels = x.size() / pixels;
  std::vector<bool> changed(pixels, false);
  for (std::size_t p = 0; p < pixels; ++p) {
    double diff = 0.0, sum = 0.0;
    for (std::size_t c = 0; c < 3; ++c) {
      diff += std::abs(double(x[p * channels + c]) - double(y[p * channels + c]));
      sum += std::abs(double(x[p * channels + c]));
    }
    changed[p] = diff > 0.02 * sum;
  }
  return changed;
}

// The correlation over the pixels `where` says between two frame differences, a - b and c - d (colour channels).
double differenceCorrelation(const RenderResult& a, const RenderResult& b, const RenderResult& c, const RenderResult& d,
                             const std::vector<bool>& where) {
  const std::size_t channels = a.frame->linear.values.size() / where.size();
  double sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0, n = 0.0;
  for (std::size_t i = 0; i < a.frame->linear.values.size(); ++i) {
    if (!where[i / channels] || i % channels > 2) continue;
    const double x = double(a.frame->linear.values[i]) - double(b.frame->linear.values[i]);
    const double y = double(c.frame->linear.values[i]) - double(d.frame->linear.values[i]);
    sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y, n += 1.0;
  }
  const double cov = sxy - sx * sy / n, vx = sxx - sx * sx / n, vy = syy - sy * sy / n;
  return vx > 0.0 && vy > 0.0 ? cov / std::sqrt(vx * vy) : 0.0;
}

RenderRequest rasterFrame(RasterMode raster) {
  RenderRequest r = variedFrame(LutMode::Physical);
  r.scene.render.width = 128;
  r.scene.render.height = 96;
  r.scene.density.totalStrands = 2000;
  r.scene.render.raster = raster;
  // What varies between two compute renders is left out as far as it can be: list drops (which entries go
  // depends on atomics' order), the opacity maps' splats and the skin's bounce.
  r.rasterSettings.tileBudget = 1u << 20;
  r.opacity.enabled = false;
  r.look.skinBounce = false;
  r.scene.render.msaa = 1;  // lavapipe draws 4-sample ribbons 5x slower; each frame is compared with its own kind
  return r;
}

// The device shading takes each strand's tilt and roughness (MarschnerParams.caustic.z and w, strandTilt and
// strandRoughness from the strand's random value: the graphics raster's vertex-to-fragment varying, the compute
// raster's shade pass): the same frame with and without the variation differs. The graphics raster is
// deterministic: its two renders of one setting are identical, so any change is the variation's. The compute
// raster's compositing order within a depth bin follows its atomics, so two of its renders differ (up to 1.3e-4
// of the frame's radiance on lavapipe, 2% over the highlights the roughness moves); both are therefore compared
// over the pixels the variation changed by more than 2% in the graphics raster, where the compute raster's
// change must be of the graphics raster's size and follow it pixel by pixel (a correlation above 0.3: the
// renders' own difference does not correlate with the variation's). Measured on lavapipe over those pixels (~156
// for the tilt, 59-74 for the roughness): tilt 4 deg, graphics 0.042, compute 0.048 (two renders 0.0007-0.0027),
// correlation 0.60-0.64; roughness 25%, graphics 0.033-0.035, compute 0.031-0.033 (two renders 0.007-0.022),
// correlation 0.64; with the shade pass's roughness cut, compute read 0.0002-0.007, correlation -0.08 to 0.
// (The tilt's cut read a change of 4.2e-5 of the whole frame, before this masked form.)
void expectBothRastersShadeTheVariation(const vk::Context& ctx, const char* what, void (*leaveOut)(HairMaterial&)) {
  std::vector<bool> where;
  double graphicsChange = 0.0;
  RenderResult graphicsA, graphicsC;
  for (RasterMode raster : {RasterMode::Graphics, RasterMode::Compute}) {
    const RenderRequest varied = rasterFrame(raster);
    RenderRequest plain = varied;
    leaveOut(plain.scene.material);
    const HairAsset asset = buildSceneAsset(varied.scene);
    const RenderResult a = renderStill(ctx, asset, varied), b = renderStill(ctx, asset, varied),
                       c = renderStill(ctx, asset, plain);
    ASSERT_TRUE(a.frame && b.frame && c.frame);
    if (raster == RasterMode::Graphics) where = changedPixels(a, c), graphicsA = a, graphicsC = c;
    const std::size_t pixels = std::size_t(std::count(where.begin(), where.end(), true));
    const double same = relativeChange(a, b, where), change = relativeChange(a, c, where);
    std::cout << rasterModeName(raster) << ": " << what << " against none: mean change " << change << " over the "
              << pixels << " pixels it changed by 2% in the graphics raster (two renders: " << same
              << "); whole frame " << relativeChange(a, c) << " (two renders: " << relativeChange(a, b) << ")\n";
    ASSERT_GT(pixels, 20u);  // 59-158 on lavapipe
    if (raster == RasterMode::Graphics) {
      EXPECT_EQ(same, 0.0);
      graphicsChange = change;
    } else {
      const double correlation = differenceCorrelation(a, c, graphicsA, graphicsC, where);
      std::cout << "  correlation with the graphics raster's change: " << correlation << "\n";
      EXPECT_GT(change, 0.5 * graphicsChange);
      EXPECT_GT(correlation, 0.3) << "the change should follow the graphics raster's, pixel by pixel";
    }
  }
}
}  // namespace

TEST_F(VulkanTest, EachStrandsTiltReachesTheShadingOfBothRasters) {
  expectBothRastersShadeTheVariation(*ctx, "tilt 4 deg", [](HairMaterial& m) { m.tiltVariation = 0.0; });
}

TEST_F(VulkanTest, EachStrandsRoughnessReachesTheShadingOfBothRasters) {
  expectBothRastersShadeTheVariation(*ctx, "roughness 25%", [](HairMaterial& m) { m.roughnessVariation = 0.0; });
}
