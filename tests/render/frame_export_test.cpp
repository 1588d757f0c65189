// `render --export-frame` and `hairpipe reference` on one small frame (96x72, 2000 strands, from behind):
//  1. the export holds the strands as drawn (points, widths from the per-strand scale and the
//     root-to-tip taper, colours from the per-strand lightness) and the camera that produced the view
//     matrix; reading the folder back returns every number bit for bit; a broken export is refused
//     naming the file;
//  2. the real-time image against the path-traced reference of the exported frame over the hair
//     (real-time hair coverage > 0.5), and two seeds of the reference against each other: PSNR and
//     mean-luminance ratio above thresholds set under what was measured (numbers in docs/SHADING.md);
//  3. the default physical model on dense hair (64x48, the default 20000 strands, default view) against its
//     reference: mean luminance and hue (red/blue) over the hair. This caught the real-time ambient
//     term returning exp(-2 sigma_a) of the sky unoccluded (1.45x too bright, red/blue 1.8x the reference's).
//  4. the compute raster's coverage of the default view's partly covered pixels against the path tracer's
//     (first hits on fibres): caught alpha compositing counting sheets of strands as independent.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/core/error.h"
#include "samples/tools/frame_export.h"
#include "samples/tools/image_compare.h"
#include "samples/tools/reference/fibre.h"
#include "samples/tools/reference/path_tracer.h"
#include "samples/tools/render_job.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
RenderRequest smallFrame() {
  RenderRequest r;
  r.scene.render.width = 96;
  r.scene.render.height = 72;
  r.scene.camera.orbitDeg = 145.0f;  // the hair side of the head
  r.scene.density.totalStrands = 2000;
  r.settleFrames = 2;
  r.captureFrame = true;
  // The paper's model: its exact S costs ~1 us on the CPU, the physical model's far more (its frames are
  // measured against the reference in docs/SHADING.md, not here).
  r.lutMode = LutMode::Float;
  r.opacity.deep = false;  // see kLuminanceRatioLow
  r.look.wrap = 0.5f;      // likewise
  return r;
}

void expectSameFrames(const ExportedFrame& a, const ExportedFrame& b) {
  EXPECT_EQ(a.strands.strandCount, b.strands.strandCount);
  EXPECT_EQ(a.strands.points, b.strands.points);
  EXPECT_EQ(a.strands.thickness, b.strands.thickness);
  EXPECT_EQ(a.strands.colors, b.strands.colors);
  EXPECT_EQ(a.camera.position, b.camera.position);
  EXPECT_EQ(a.camera.target, b.camera.target);
  EXPECT_EQ(a.camera.up, b.camera.up);
  EXPECT_EQ(a.camera.fovYDeg, b.camera.fovYDeg);
  EXPECT_EQ(a.camera.width, b.camera.width);
  EXPECT_EQ(a.camera.height, b.camera.height);
  ASSERT_EQ(a.lights.size(), b.lights.size());
  for (std::size_t i = 0; i < a.lights.size(); ++i) {
    EXPECT_EQ(a.lights[i].type, b.lights[i].type);
    EXPECT_EQ(a.lights[i].direction, b.lights[i].direction);
    EXPECT_EQ(a.lights[i].color * a.lights[i].intensity, b.lights[i].color * b.lights[i].intensity);
    EXPECT_EQ(a.lights[i].shadows, b.lights[i].shadows);
  }
  EXPECT_TRUE(a.material == b.material);
  EXPECT_EQ(a.strandTilts, b.strandTilts);
  EXPECT_EQ(a.headPositions, b.headPositions);
  EXPECT_EQ(a.headNormals, b.headNormals);
  EXPECT_EQ(a.headAlbedo, b.headAlbedo);
  EXPECT_EQ(a.headIndices, b.headIndices);
  EXPECT_EQ(a.hairAlbedo, b.hairAlbedo);
  EXPECT_EQ(a.environment, b.environment);
  EXPECT_EQ(a.background, b.background);
  EXPECT_EQ(a.exposure, b.exposure);
  EXPECT_EQ(a.fibreModel, b.fibreModel);
}

// Measured on lavapipe with these settings (the paper's model, float LUTs, global opacity slices, the skin's
// bounce on; 16 spp, 4 bounces; a8f24a4): real time against the reference 20.0 dB, luminance ratio 0.852
// (0.900 and 20.7 dB with the default groom, 2026-11-27); seed 1 against seed 2: 20.2 dB, ratio 1.026 (0.960
// with the groom; 16 spp is noise-limited), and the compute raster's atomics
// order moves the frame by up to 1.7%. The lower luminance bound is that measurement less twice the seeds'
// spread; the reference under a sun of a quarter of the intensity (ratio 1.72; half: 1.28) must fail the upper
// one. The test catches a broken camera, width, light or tonemap, not a 1 dB change. The test keeps global slices, the
// lighting its bounds were set for (with the default deep maps this sparse 2,000-strand frame measured
// 0.805); the default lighting is measured against the reference by the physical-model tests below and in
// docs/SHADING.md "Real time against the reference". So does the head's wrap term of 0.5 (the default before
// the skin's indirect light): at the default wrap 0 this frame of the paper's model measured 0.750, 20.96 dB
// (its hair scatters more onto the skin in the reference than the real-time skin receives); the physical
// model's sparse frame against its 64 spp, 8-bounce reference gains there instead (SHADING.md "The skin's
// indirect light").
constexpr double kMinPsnrAgainstReference = 19.0, kMinPsnrBetweenSeeds = 19.0;
constexpr double kLuminanceRatioLow = 0.80, kLuminanceRatioHigh = 1.25;

void expectCloseToReference(const FrameCapture& capture, const ExportedFrame& frame) {
  const reference::TraceResult a = reference::traceReference(frame, {16, 4, 1, 0, nullptr});
  const reference::TraceResult b = reference::traceReference(frame, {16, 4, 2, 0, nullptr});
  ExportedFrame dimSun = frame;
  dimSun.lights[0].intensity *= 0.25f;
  const reference::TraceResult dim = reference::traceReference(dimSun, {16, 4, 1, 0, nullptr});
  const ImageComparison realTime = compareImages(capture.linear, a.radiance, capture.hairAlpha, frame.exposure);
  const ImageComparison seeds = compareImages(a.radiance, b.radiance, capture.hairAlpha, frame.exposure);
  const ImageComparison wrongLight = compareImages(capture.linear, dim.radiance, capture.hairAlpha, frame.exposure);
  std::cout << "real time vs reference: " << realTime.psnrDb << " dB, luminance " << realTime.luminanceRatio
            << "; seeds: " << seeds.psnrDb << " dB, luminance " << seeds.luminanceRatio << ", " << realTime.pixels
            << " hair pixels; against a sun of a quarter of the intensity: luminance " << wrongLight.luminanceRatio << "\n";
  EXPECT_GT(realTime.pixels, 500u);
  EXPECT_GT(realTime.psnrDb, kMinPsnrAgainstReference);
  EXPECT_GT(realTime.luminanceRatio, kLuminanceRatioLow);
  EXPECT_LT(realTime.luminanceRatio, kLuminanceRatioHigh);
  EXPECT_GT(seeds.psnrDb, kMinPsnrBetweenSeeds);
  EXPECT_NEAR(seeds.luminanceRatio, 1.0, 0.05);
  EXPECT_GT(wrongLight.luminanceRatio, kLuminanceRatioHigh) << "the negative control should fail the bounds";
}
}  // namespace

TEST_F(VulkanTest, FrameExportRoundTripsAndTheRealTimeHairMatchesTheReference) {
  const RenderRequest request = smallFrame();
  const HairAsset asset = buildSceneAsset(request.scene);
  const RenderResult result = renderStill(*ctx, asset, request);
  ASSERT_TRUE(result.frame);
  const FrameCapture& capture = *result.frame;
  const ExportedFrame frame =
      makeExportedFrame(request, asset, capture, reference::fibreModelName(fibreModelOf(request.lutMode)));
  EXPECT_EQ(frame.fibreModel, "marschner");

  // The strands as drawn (shaders/strands.vert's width and the shading's lightness scale).
  const std::uint32_t q = capture.verticesPerStrand;
  ASSERT_EQ(frame.strands.strandCount, result.strands);
  const std::vector<float> scales = frame.strandColorScales();
  for (std::uint32_t s = 0; s < frame.strands.strandCount; ++s) {
    const auto& attr = capture.strands.attributes[s];
    EXPECT_NEAR(scales[s], attr.colorScale, 1e-6f * attr.colorScale);
    for (std::uint32_t j = 0; j < q; ++j) {
      const std::size_t i = std::size_t(s) * q + j;
      const glm::vec4 p = capture.strands.positions[i];
      ASSERT_EQ(frame.strands.points[i], glm::vec3(p));
      const float width = request.look.strandWidth * attr.widthScale * glm::mix(1.0f, request.look.tipWidthFraction, p.w);
      ASSERT_NEAR(frame.strands.thickness[i], width, 1e-6f * width);
      ASSERT_EQ(frame.strands.colors[i], frame.hairAlbedo * attr.colorScale);
    }
  }
  // The camera the export describes gives the view matrix that drew the frame.
  const glm::mat4 view = glm::lookAtRH(frame.camera.position, frame.camera.target, frame.camera.up);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(view[c][r], capture.camera.view[c][r], 1e-6f);
  EXPECT_FLOAT_EQ(glm::radians(frame.camera.fovYDeg), capture.camera.fovY);
  ASSERT_EQ(capture.linear.width, 96u);
  ASSERT_EQ(capture.hairAlpha.width, 96u);

  const auto dir = std::filesystem::temp_directory_path() / "hairpipe_frame_export_test";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  writeFrameExport(dir, frame);
  const ExportedFrame back = readFrameExport(dir);
  expectSameFrames(frame, back);
  expectCloseToReference(capture, back);
  writePfm(dir / "realtime.pfm", capture.linear);
  EXPECT_EQ(readPfm(dir / "realtime.pfm").values, capture.linear.values);

  // A broken export is refused, naming the file.
  std::ofstream(dir / "frame.json") << "{\"format\": \"hairpipe-frame\"}";
  try {
    readFrameExport(dir);
    ADD_FAILURE() << "a frame.json without a version was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("frame.json"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

// The default scene at 64x48 after 2 settling frames, captured for a comparison with the reference.
RenderRequest smallCapturedFrame() {
  RenderRequest request;
  request.scene.render.width = 64;
  request.scene.render.height = 48;
  request.settleFrames = 2;
  request.captureFrame = true;
  return request;
}

// The default frame (physical fibres, deep maps, skin bounce, compute raster over a 4-sample head) against
// the reference over the hair, 64x48, reference 32 spp / 4 bounces. Measured on lavapipe (a8f24a4) against
// reference seeds 1-3: 30.6-31.7 dB, luminance 1.028-1.070 (seed 1: 1.011 since the far side's sky follows the
// head's depth), red/blue 0.94-1.01 of the reference's (whose own
// red/blue spreads 1.78-1.92 at 32 spp). With the Lambertian head and its indirect light (2026-11-29): 29.4 /
// 30.4 / 30.3 dB, luminance 0.984 / 0.969 / 0.977 (wrap 0.5 in the same build: 31.0 / 31.6 / 31.1 dB, 1.039 /
// 1.020 / 1.028; three runs of seed 1 within 0.02 dB). This frame's hair pixels are mostly its edges over
// the skin, and its lowest band (the hair beside the neck) reads 0.90 of the reference's luminance (1.07 with
// the wrap): the light the hair scatters onto the skin behind it, which the wrap stood in for, is missing;
// at 160x120 after 90 frames the front view is unchanged (SHADING.md "The skin's indirect light"). Bounds: 29 dB, the luminance within [0.95, 1.15] and the hue within
// 15%, about twice the seeds' spread around the measurement. Negative controls, measured earlier: a
// single-sample head (the head's edges over the hair aliased, half-skin pixels drawn as hair) read 22.0-22.4
// dB, luminance 0.73-0.75; the old ambient term, albedo exp(-2 sigma_a) unoccluded (80x60, 16 spp), luminance
// 1.45, red/blue 3.19 against 1.80: each fails the luminance bound, the second the hue bound too.
TEST_F(VulkanTest, DensePhysicalHairMatchesTheReferenceLuminanceAndHue) {
  RenderRequest request = smallCapturedFrame();
  ASSERT_EQ(request.lutMode, LutMode::Physical);
  ASSERT_EQ(request.scene.render.msaa, 4u);
  const HairAsset asset = buildSceneAsset(request.scene);
  const RenderResult result = renderStill(*ctx, asset, request);
  ASSERT_TRUE(result.frame);
  const ExportedFrame frame = makeExportedFrame(request, asset, *result.frame, "physical");
  const reference::TraceResult ref = reference::traceReference(frame, {32, 4, 1, 0, nullptr});
  const ImageComparison c = compareImages(result.frame->linear, ref.radiance, result.frame->hairAlpha, frame.exposure);
  std::cout << "physical, dense hair: " << c.psnrDb << " dB, luminance " << c.luminanceRatio << ", red/blue "
            << c.redBlueImage << " vs " << c.redBlueReference << ", " << c.pixels << " hair pixels\n";
  EXPECT_GT(c.pixels, 200u);
  EXPECT_GT(c.psnrDb, 29.0);
  EXPECT_GT(c.luminanceRatio, 0.95);
  EXPECT_LT(c.luminanceRatio, 1.15);
  EXPECT_GT(c.redBlueImage / c.redBlueReference, 0.85);
  EXPECT_LT(c.redBlueImage / c.redBlueReference, 1.15);
}

// The compute raster reads the head's depth samples: where the skin's edge is in front of hair (the jaw
// and neck over the hair behind them) each sample takes the hair in front of it, so those pixels mix skin
// and hair as the reference's do, instead of all hair (sample at the centre behind the skin's edge: the
// pixel drawn as hair) or all skin. The same 64x48 frame with 4 head samples and with 1, against one
// reference (32 spp, 4 bounces). Measured on lavapipe: 30.3 against 22.4 dB, luminance ratio 1.02 against
// 0.73 (docs/SHADING.md "The head's edges over the hair"). Where both cover a pixel fully the frames agree
// (0.9997): a composite that left the sample mask unwritten on its single-sample path drew 1.92x there.
TEST_F(VulkanTest, HeadSamplesAntialiasTheSkinsEdgeOverTheHair) {
  RenderRequest request = smallCapturedFrame();
  const HairAsset asset = buildSceneAsset(request.scene);
  const RenderResult multisampled = renderStill(*ctx, asset, request);
  request.scene.render.msaa = 1;
  const RenderResult single = renderStill(*ctx, asset, request);
  ASSERT_TRUE(multisampled.frame && single.frame);
  const ExportedFrame frame = makeExportedFrame(request, asset, *multisampled.frame, "physical");
  const reference::TraceResult ref = reference::traceReference(frame, {32, 4, 1, 0, nullptr});
  const auto against = [&](const RenderResult& r) {
    return compareImages(r.frame->linear, ref.radiance, r.frame->hairAlpha, frame.exposure);
  };
  const ImageComparison four = against(multisampled), one = against(single);
  std::cout << "head samples 4: " << four.psnrDb << " dB, luminance " << four.luminanceRatio << "; 1: " << one.psnrDb
            << " dB, luminance " << one.luminanceRatio << "\n";
  EXPECT_GT(four.psnrDb, one.psnrDb + 4.0);
  EXPECT_LT(std::abs(four.luminanceRatio - 1.0), std::abs(one.luminanceRatio - 1.0) - 0.1);
  // Coverage at the head's edges comes in quarters of the samples, never above one.
  std::size_t partial = 0;
  for (float a : multisampled.frame->hairAlpha.values) {
    EXPECT_LE(a, 1.0f + 1e-3f);
    partial += (a > 0.02f && a < 0.98f) ? 1 : 0;
  }
  EXPECT_GT(partial, 10u);
  // Away from the edges the two frames draw the same hair: the single-sample composite draws every sample.
  double sum4 = 0.0, sum1 = 0.0;
  std::size_t covered = 0;
  const LinearImage &image4 = multisampled.frame->linear, &image1 = single.frame->linear;
  for (std::size_t i = 0; i < image4.values.size() / 3; ++i) {
    if (multisampled.frame->hairAlpha.values[i] < 0.98f || single.frame->hairAlpha.values[i] < 0.98f) continue;
    ++covered;
    for (std::size_t c = 0; c < 3; ++c) sum4 += image4.values[i * 3 + c], sum1 += image1.values[i * 3 + c];
  }
  std::cout << covered << " pixels covered in both, radiance 1 / 4 samples " << sum1 / sum4 << "\n";
  EXPECT_GT(covered, 100u);
  EXPECT_NEAR(sum1 / sum4, 1.0, 0.05);
}

// The same frame without and with the skin's bounce (a small compute-raster frame, sky off, captured).
// `request` is left as the second frame was rendered, for the export.
// The sum of an image's linear values over the pixels `mask` (a frame's hair alpha) covers more than half.
double sumOverHair(const LinearImage& image, const LinearImage& mask) {
  const std::size_t channels = image.values.size() / mask.values.size();
  double sum = 0.0;
  for (std::size_t p = 0; p < mask.values.size(); ++p)
    if (mask.values[p] > 0.5f)
      for (std::size_t c = 0; c < channels; ++c) sum += image.values[p * channels + c];
  return sum;
}

struct BounceFrames {
  HairAsset asset;
  RenderResult without, with;
};
BounceFrames renderWithAndWithoutBounce(const vk::Context& ctx, RenderRequest& request, std::uint32_t width,
                                        std::uint32_t height) {
  request.scene.render.width = width;
  request.scene.render.height = height;
  request.scene.render.raster = RasterMode::Compute;
  request.settleFrames = 2;
  request.captureFrame = true;
  request.look.ambient = 0.0f;
  BounceFrames f{buildSceneAsset(request.scene), {}, {}};
  request.look.skinBounce = false;
  f.without = renderStill(ctx, f.asset, request);
  request.look.skinBounce = true;
  f.with = renderStill(ctx, f.asset, request);
  return f;
}

// The light the skin sends to the hair, real time against the reference, with the defaults (dual
// scattering, deep maps at their default bias): the frame with the skin's bounce minus the frame without it,
// against the reference of the same exported frame minus that reference with black skin (traced with the
// same seed, so the two share their paths up to the skin), summed over the pixels the hair covers fully in
// the reference (partly covered pixels also see the skin itself). Sky off, default view, 128x96, 16 spp,
// 3 bounces.
struct SkinShare {
  double realTime = 0.0, reference = 0.0;
  std::size_t pixels = 0;
};
SkinShare skinShareAgainstTheReference(const vk::Context& ctx, RenderRequest& request, std::uint64_t seed) {
  const BounceFrames frames = renderWithAndWithoutBounce(ctx, request, 128, 96);
  if (!frames.without.frame || !frames.with.frame) return {};
  ExportedFrame frame = makeExportedFrame(request, frames.asset, *frames.with.frame, "physical");
  const reference::TraceResult lit = reference::traceReference(frame, {16, 3, seed, 0, nullptr});
  std::fill(frame.headAlbedo.begin(), frame.headAlbedo.end(), decltype(frame.headAlbedo)::value_type(0.0f));
  const reference::TraceResult black = reference::traceReference(frame, {16, 3, seed, 0, nullptr});
  SkinShare share;
  const std::vector<float>& coverage = lit.hairCoverage.values;
  for (std::size_t p = 0; p < coverage.size(); ++p) {
    if (coverage[p] < 0.98f) continue;
    ++share.pixels;
    for (std::size_t c = 0; c < 3; ++c) {
      share.realTime += frames.with.frame->linear.values[p * 3 + c] - frames.without.frame->linear.values[p * 3 + c];
      share.reference += (lit.radiance.values[p * 3 + c] - black.radiance.values[p * 3 + c]) * frame.exposure;
    }
  }
  return share;
}

// Measured on lavapipe, seeds 1 / 2 / 3 (the reference's noise at 16 spp; the real-time frames are the
// same): the skin adds 1.03 / 1.12 / 1.17 of what it adds in the reference with the defaults, 0.85 / 0.93 /
// 0.98 with single scattering (which this noise cannot tell apart). Asserted for seed 1: within [0.85, 1.35],
// the seeds' spread with a margin on either side; without the bounce it adds 0 (the frame would fail).
TEST_F(VulkanTest, SkinBounceAddsWhatTheReferencesSkinAdds) {
  RenderRequest request;
  const SkinShare share = skinShareAgainstTheReference(*ctx, request, 1);
  std::cout << share.pixels << " fully covered hair pixels; the skin adds " << share.realTime << " in real time, "
            << share.reference << " in the reference: " << share.realTime / share.reference << "\n";
  ASSERT_GT(share.pixels, 500u);
  ASSERT_GT(share.reference, 0.0);
  EXPECT_GT(share.realTime / share.reference, 0.85);
  EXPECT_LT(share.realTime / share.reference, 1.35);
}

// The skin's bounce gathered along the guides and blended into each render strand (the default), against
// the gather along every render strand, both at 8 points per strand; default view, 128x96, sky off. The
// bounce is the light the frame gains with it over the hair pixels. Measured on lavapipe: gathered along
// every strand it adds 0.197 of the hair's light, blended from the guides 0.191 (-3%); the frames 53.2 dB
// apart. A linear blend of the guides' bounce added 17% more than the gather along the strands, the mean of
// the linear and the log blend 7.5% more. Asserted: within 10%, frames above 45 dB.
TEST_F(VulkanTest, SkinBounceBlendedFromTheGuidesAddsWhatTheGatherAlongEveryStrandAdds) {
  RenderRequest request;
  request.bounceAtGuides = false;
  const BounceFrames strands = renderWithAndWithoutBounce(*ctx, request, 128, 96);
  request.bounceAtGuides = true;
  const RenderResult guides = renderStill(*ctx, strands.asset, request);
  ASSERT_TRUE(strands.without.frame && strands.with.frame && guides.frame);
  const LinearImage& mask = guides.frame->hairAlpha;
  const double off = sumOverHair(strands.without.frame->linear, mask);
  const double alongStrands = sumOverHair(strands.with.frame->linear, mask);
  const double fromGuides = sumOverHair(guides.frame->linear, mask);
  const ImageComparison between = compareImages(guides.frame->linear, strands.with.frame->linear, mask, 1.0f);
  std::cout << "the bounce adds " << alongStrands / off - 1.0 << " of the hair's light gathered along every strand, "
            << fromGuides / off - 1.0 << " blended from the guides; the frames " << between.psnrDb << " dB, luminance "
            << between.luminanceRatio << "\n";
  ASSERT_GT(alongStrands, 1.05 * off);  // there is a bounce to compare
  EXPECT_NEAR((fromGuides - off) / (alongStrands - off), 1.0, 0.10);
  EXPECT_GT(between.psnrDb, 45.0);
  EXPECT_LT(between.psnrDb, 80.0);  // the frames differ: the option reached the renderer (two identical: 99 dB)
}

// Coverage of the default view's hair (128x96, the default 20,000 strands) against the path tracer's
// (the fraction of camera rays whose first hit is a fibre, 16 stratified rays per pixel), on the pixels
// the hair covers only partly in the reference: the silhouettes and sparse tips. Strands interpolated
// between the same guides lie in sheets; alpha compositing's independent "over" counted their overlap
// as if independent and covered these 377 pixels 0.631 against the reference's 0.574 (lavapipe); the
// 8 x 8 overlap mask of raster_fine.glsl gives 0.572 over a single-sample head, 0.556 over the default 4
// samples (whose skin edges hide hair per sample, like the reference's rays). Asserted: within 0.03 (16 rays
// a pixel: ~0.01 noise).
TEST_F(VulkanTest, ComputeRasterCoversSilhouettePixelsLikeThePathTracer) {
  RenderRequest request;
  request.scene.render.width = 128;
  request.scene.render.height = 96;
  request.scene.render.raster = RasterMode::Compute;
  request.settleFrames = 2;
  request.captureFrame = true;
  request.look.ambient = 0.0f;
  const HairAsset asset = buildSceneAsset(request.scene);
  const RenderResult result = renderStill(*ctx, asset, request);
  ASSERT_TRUE(result.frame);
  const ExportedFrame frame = makeExportedFrame(request, asset, *result.frame, "physical");
  const reference::TraceResult ref = reference::traceReference(frame, {16, 1, 1, 0, nullptr});
  const std::vector<float>& alpha = result.frame->hairAlpha.values;
  const std::vector<float>& coverage = ref.hairCoverage.values;
  ASSERT_EQ(alpha.size(), coverage.size());
  double realTime = 0.0, traced = 0.0;
  std::size_t pixels = 0;
  for (std::size_t p = 0; p < alpha.size(); ++p)
    if (coverage[p] > 0.02f && coverage[p] < 0.98f) realTime += alpha[p], traced += coverage[p], ++pixels;
  ASSERT_GT(pixels, 100u);
  std::cout << "partly covered pixels: " << pixels << ", coverage real time " << realTime / pixels << ", traced "
            << traced / pixels << "\n";
  EXPECT_NEAR(realTime / pixels, traced / pixels, 0.03);
}

// The bounce map under a spot light (a perspective head map; the texel size in RenderFrame::headBounce.y
// from its framing): every value of the frame finite, and the bounce adds light to the hair (measured on
// lavapipe: +7.0% over the hair pixels; asserted > +1%).
TEST_F(VulkanTest, SkinBounceUnderASpotIsFiniteAndAddsLight) {
  RenderRequest request;
  request.scene.lights = {LightSpec::makeSpot({0.3f, 0.4f, 0.6f}, {0.0f, -0.08f, 0.0f}, 40.0f)};
  const BounceFrames frames = renderWithAndWithoutBounce(*ctx, request, 96, 72);
  const RenderResult& without = frames.without;
  const RenderResult& with = frames.with;
  ASSERT_TRUE(without.frame && with.frame);
  for (std::size_t i = 0; i < with.frame->linear.values.size(); ++i)
    ASSERT_TRUE(std::isfinite(with.frame->linear.values[i])) << "value " << i;
  const double sumWithout = sumOverHair(without.frame->linear, with.frame->hairAlpha);
  const double sumWith = sumOverHair(with.frame->linear, with.frame->hairAlpha);
  std::cout << "spot: the hair's linear sum with the bounce / without " << sumWith / sumWithout << "\n";
  EXPECT_GT(sumWith, 1.01 * sumWithout);
}

// The skin's bounce gathered at 8 points per strand (StrandOptions::bounceSamples, the default; along the
// guides, blended into the strands, the default too) and interpolated, against the gather at all 36
// vertices, default view, 128x96, sky off. The bounce is the light the frame gains with it (over the hair
// pixels). Measured on lavapipe: it adds 0.1957 of the hair's light gathered at every vertex, 0.1909 at 8
// points (0.976x; along every strand instead of the guides 0.1984 and 0.1979, and 1.08x with the chord alone
// between the points, bounce_samples.glsl); the frames 53.5 dB apart, luminance 0.996. Asserted: the
// 8-point bounce within 15% of the every-vertex one, and the frames above 40 dB PSNR against each other.
TEST_F(VulkanTest, SkinBounceAtEightPointsPerStrandMatchesTheGatherAtEveryVertex) {
  RenderRequest request;
  request.bounceSamples = 36;
  const BounceFrames every = renderWithAndWithoutBounce(*ctx, request, 128, 96);
  request.bounceSamples = 8;
  request.look.skinBounce = true;
  const RenderResult eight = renderStill(*ctx, every.asset, request);
  ASSERT_TRUE(every.without.frame && every.with.frame && eight.frame);
  const LinearImage& mask = every.with.frame->hairAlpha;
  const double off = sumOverHair(every.without.frame->linear, mask);
  const double all = sumOverHair(every.with.frame->linear, mask);
  const double sampled = sumOverHair(eight.frame->linear, mask);
  const ImageComparison cmp = compareImages(eight.frame->linear, every.with.frame->linear, mask, 1.0f);
  std::cout << "the bounce adds " << all / off - 1.0 << " of the hair's light at every vertex, " << sampled / off - 1.0
            << " at 8 points; the frames: " << cmp.psnrDb << " dB, luminance " << cmp.luminanceRatio << "\n";
  ASSERT_GT(all, 1.05 * off);  // the bounce is there to be sampled
  EXPECT_NEAR((sampled - off) / (all - off), 1.0, 0.15);
  EXPECT_GT(cmp.psnrDb, 40.0);
}
