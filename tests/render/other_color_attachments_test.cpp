// hairpipe's draws inside an application's rendering with more colour attachments than hairpipe writes
// (AttachmentFormats::otherColors: an engine's velocity and normal targets in its main pass): its pipelines
// match that rendering, leave every other attachment as the application cleared it, and draw the same first
// colour as in a rendering of that colour alone; with both rasters, under synchronization validation. With
// RendererSettings::velocityOutput the compute raster's composite writes the hair's motion into one of them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/shading/half_float.h"
#include "compute/renderer/renderer.h"
#include "engine/vk/attachments.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/image.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "tests/support/refusal.h"
#include "tests/support/small_frame.h"
#include "tests/support/vk_fixture.h"

using hp::test::VulkanTest;

namespace {
constexpr VkFormat kColor = VK_FORMAT_R16G16B16A16_SFLOAT, kDepth = VK_FORMAT_D32_SFLOAT;
// The application's others: a velocity target and an 8-bit normal target, cleared to values hairpipe's
// draws would not write.
const std::vector<VkFormat> kOthers = {VK_FORMAT_R16G16_SFLOAT, VK_FORMAT_R8G8B8A8_UNORM};
// Clear values each format holds exactly: halves 3 and -2 (0x4200, 0xC000), bytes 51, 102, 204, 255.
const VkClearColorValue kOtherClears[] = {{{3.0f, -2.0f, 0.0f, 0.0f}}, {{0.2f, 0.4f, 0.8f, 1.0f}}};
const std::uint16_t kVelocityClear[2] = {0x4200, 0xC000};
const std::uint8_t kNormalClear[4] = {51, 102, 204, 255};

hp::vk::Image attachmentImage(const hp::vk::Context& ctx, VkFormat format, VkImageUsageFlags usage, const std::string& name,
                              VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT) {
  hp::vk::ImageDesc d;
  d.samples = samples;
  d.width = hp::test::kSmallWidth;
  d.height = hp::test::kSmallHeight;
  d.format = format;
  d.usage = usage | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  d.name = name;
  return hp::vk::Image(ctx, d);
}

// A four-channel velocity target whose last two channels hold the engine's own values (halves 0.25, 0.5).
constexpr VkFormat kWideVelocity = VK_FORMAT_R16G16B16A16_SFLOAT;
const VkClearColorValue kWideVelocityClear = {{3.0f, -2.0f, 0.25f, 0.5f}};
const std::uint16_t kWideVelocityBlueAlpha[2] = {0x3400, 0x3800};

VkClearColorValue clearOf(VkFormat format) {
  return format == kOthers[0] ? kOtherClears[0] : format == kWideVelocity ? kWideVelocityClear : kOtherClears[1];
}

hp::RendererSettings frameSettings(hp::RasterMode raster, bool others, VkSampleCountFlagBits samples) {
  hp::RendererSettings s;
  s.formats = {kColor, kDepth, samples};
  if (others) s.formats.otherColors = kOthers;
  s.raster = raster;
  s.opacity.resolution = 256;
  return s;
}

// One frame of `view` (`strands` render strands) drawn into the application's colour, depth and other colour attachments
// (s.formats: each other one cleared to its kOtherClears value; an UNDEFINED one a slot left unused, a null
// view), resolved where multisampled by the last rendering. Returns every colour attachment's bytes (none for
// an unused slot), the first colour first; with `coverage`, also the compute raster's coverage per pixel.
std::vector<std::vector<std::byte>> drawFrame(const hp::vk::Context& ctx, const hp::RendererSettings& s,
                                              const hp::View& view, std::vector<float>* coverage = nullptr,
                                              std::uint32_t strands = 500) {
  const hp::RasterMode raster = s.raster;
  const VkSampleCountFlagBits samples = s.formats.samples;
  hp::Renderer renderer(ctx, s);
  auto hair = renderer.createInstance(hp::test::defaultHeadWithStrands(strands), {});
  hp::HairInstance* one[] = {hair.get()};
  const bool msaa = samples != VK_SAMPLE_COUNT_1_BIT;
  std::vector<VkFormat> formats = {kColor};
  formats.insert(formats.end(), s.formats.otherColors.begin(), s.formats.otherColors.end());
  std::vector<hp::vk::Image> colors, resolved;
  for (std::size_t i = 0; i < formats.size(); ++i) {
    const std::string name = i == 0 ? "colour" : "other " + std::to_string(i);
    const bool unused = formats[i] == VK_FORMAT_UNDEFINED;
    colors.push_back(unused ? hp::vk::Image() : attachmentImage(ctx, formats[i], VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, name, samples));
    if (msaa)
      resolved.push_back(unused ? hp::vk::Image()
                                : attachmentImage(ctx, formats[i], VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, name + " resolved"));
  }
  const auto eachImage = [](std::vector<hp::vk::Image>& images, const std::function<void(hp::vk::Image&)>& f) {
    for (hp::vk::Image& image : images)
      if (image.handle() != VK_NULL_HANDLE) f(image);
  };
  const hp::vk::Image depth = attachmentImage(ctx, kDepth, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                              "depth", samples);
  const bool compute = raster == hp::RasterMode::Compute;
  if (compute) renderer.setRasterTarget(depth.extent(), depth.view(), one);
  hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    renderer.recordUpdate(cmd, 0, one);
    renderer.recordShadows(cmd, 0, hp::LightSpec{}, one);
    std::vector<VkRenderingAttachmentInfo> attachments;
    for (std::vector<hp::vk::Image>* images : {&resolved, &colors})
      eachImage(*images, [&](hp::vk::Image& image) {
        hp::vk::imageBarrier(ctx, cmd, image.handle(), VK_IMAGE_ASPECT_COLOR_BIT, hp::vk::ImageUse::Undefined,
                             hp::vk::ImageUse::ColorAttachment);
      });
    for (std::size_t i = 0; i < colors.size(); ++i) {
      attachments.push_back(hp::vk::colorAttachment(colors[i].view(), VK_ATTACHMENT_LOAD_OP_CLEAR,
                                                    i == 0 ? VkClearColorValue{} : clearOf(formats[i])));
    }
    hp::vk::imageBarrier(ctx, cmd, depth.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, hp::vk::ImageUse::Undefined,
                         hp::vk::ImageUse::DepthAttachment);
    VkRenderingAttachmentInfo depthInfo = hp::vk::depthAttachment(depth.view(), VK_ATTACHMENT_LOAD_OP_CLEAR,
                                                                   VK_ATTACHMENT_STORE_OP_STORE);
    // The last rendering resolves each multisampled colour (the average of its samples).
    const auto resolveInLastRendering = [&] {
      for (std::size_t i = 0; i < resolved.size(); ++i) {
        if (resolved[i].handle() == VK_NULL_HANDLE) continue;
        attachments[i].resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
        attachments[i].resolveImageView = resolved[i].view();
        attachments[i].resolveImageLayout = hp::vk::imageLayout(hp::vk::ImageUse::ColorAttachment);
      }
    };
    if (!compute) resolveInLastRendering();
    VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
    info.renderArea = {{0, 0}, depth.extent()};
    info.layerCount = 1;
    info.colorAttachmentCount = std::uint32_t(attachments.size());
    info.pColorAttachments = attachments.data();
    info.pDepthAttachment = &depthInfo;
    ctx.fn().vkCmdBeginRendering(cmd, &info);
    renderer.recordDraw(cmd, 0, view, one);
    ctx.fn().vkCmdEndRendering(cmd);
    if (compute) {
      hp::vk::imageBarrier(ctx, cmd, depth.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, hp::vk::ImageUse::DepthAttachment,
                           hp::vk::ImageUse::ComputeSampled);
      renderer.recordRaster(cmd, 0, view);
      hp::vk::imageBarrier(ctx, cmd, depth.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, hp::vk::ImageUse::ComputeSampled,
                           hp::vk::ImageUse::DepthAttachment);
      eachImage(colors, [&](hp::vk::Image& c) {
        hp::vk::imageBarrier(ctx, cmd, c.handle(), VK_IMAGE_ASPECT_COLOR_BIT, hp::vk::ImageUse::ColorAttachment,
                             hp::vk::ImageUse::ColorAttachment);
      });
      for (VkRenderingAttachmentInfo& a : attachments) a.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
      depthInfo.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
      resolveInLastRendering();
      ctx.fn().vkCmdBeginRendering(cmd, &info);
      renderer.recordComposite(cmd, depth.extent());
      ctx.fn().vkCmdEndRendering(cmd);
    }
  }, "other colour attachments");
  if (coverage) *coverage = renderer.rasterCoverage();
  std::vector<std::vector<std::byte>> bytes;
  for (const hp::vk::Image& c : msaa ? resolved : colors)
    bytes.push_back(c.handle() == VK_NULL_HANDLE ? std::vector<std::byte>()
                                                 : hp::vk::readbackImage(ctx, c, hp::vk::ImageUse::ColorAttachment));
  return bytes;
}

// The first two half-float channels of the velocity texel at `pixel` of `bytes` (texelBytes each).
glm::vec2 velocityAt(const std::vector<std::byte>& bytes, std::size_t pixel, std::size_t texelBytes) {
  std::uint16_t h[2];
  std::memcpy(h, bytes.data() + pixel * texelBytes, 4);
  return {hp::shading::halfToFloat(h[0]), hp::shading::halfToFloat(h[1])};
}

// Texels of `bytes` that differ from the texel `clear` (texelBytes bytes).
std::size_t texelsChanged(const std::vector<std::byte>& bytes, const void* clear, std::size_t texelBytes) {
  std::size_t n = 0;
  for (std::size_t at = 0; at + texelBytes <= bytes.size(); at += texelBytes)
    n += std::memcmp(bytes.data() + at, clear, texelBytes) != 0;
  return n;
}
}  // namespace

// Single-sampled and with 4 samples (the default: the ribbons' sample masks, the composite's two draws); the
// others also after an unused slot.
TEST_F(VulkanTest, OtherColorAttachmentsAreLeftAsTheApplicationClearedThem) {
  for (const VkSampleCountFlagBits samples : {VK_SAMPLE_COUNT_1_BIT, VK_SAMPLE_COUNT_4_BIT})
  for (const hp::RasterMode raster : {hp::RasterMode::Graphics, hp::RasterMode::Compute}) {
    SCOPED_TRACE(std::string(raster == hp::RasterMode::Compute ? "compute raster, " : "graphics raster, ") +
                 std::to_string(int(samples)) + " sample(s)");
    const hp::View view = hp::test::smallFrontView();
    const auto alone = drawFrame(*ctx, frameSettings(raster, false, samples), view);
    // The others as they are, and after a slot the rendering leaves unused (VK_FORMAT_UNDEFINED, a null view).
    for (const bool unusedSlot : {false, true}) {
      SCOPED_TRACE(unusedSlot ? "after an unused slot" : "");
      hp::RendererSettings s = frameSettings(raster, true, samples);
      if (unusedSlot) s.formats.otherColors.insert(s.formats.otherColors.begin(), VK_FORMAT_UNDEFINED);
      const auto withOthers = drawFrame(*ctx, s, view);
      const std::size_t first = unusedSlot ? 2 : 1;  // the velocity target's place in the frame
      ASSERT_EQ(withOthers.size(), first + 2);
      // The first colour as drawn alone: the head and hair drawn over a tenth of the frame at least.
      const std::uint16_t background[4] = {};
      EXPECT_GT(texelsChanged(alone[0], background, 8), std::size_t(hp::test::kSmallWidth) * hp::test::kSmallHeight / 10);
      std::size_t apart = 0;
      for (std::size_t at = 0; at < alone[0].size(); at += 8)
        apart += std::memcmp(alone[0].data() + at, withOthers[0].data() + at, 8) != 0;
      // Graphics: the same pipelines' output; compute: its run-to-run order within a depth bin (0-33 texels of
      // 15,360 apart over eight runs of both sample counts, lavapipe; the bound is 3 times that).
      std::cout << "first colour, texels apart from the frame drawn without the others: " << apart << "\n";
      EXPECT_LE(apart, raster == hp::RasterMode::Compute ? std::size_t(100) : std::size_t(0));
      EXPECT_EQ(texelsChanged(withOthers[first], kVelocityClear, 4), 0u);
      EXPECT_EQ(texelsChanged(withOthers[first + 1], kNormalClear, 4), 0u);
    }
  }
}

TEST_F(VulkanTest, OtherColorAttachmentsAreRefusedByField) {
  hp::RendererSettings s;
  s.formats = {kColor, kDepth, VK_SAMPLE_COUNT_1_BIT};
  s.formats.otherColors = {VK_FORMAT_R16G16_SFLOAT, VK_FORMAT_D32_SFLOAT};
  EXPECT_NE(hp::test::refusalOf([&] { hp::Renderer r(*ctx, s); })
                .find("RendererSettings.formats.otherColors[1] must be a colour format or VK_FORMAT_UNDEFINED, got VkFormat 126"),
            std::string::npos);
  s.formats.otherColors.assign(8, VK_FORMAT_R8G8B8A8_UNORM);
  EXPECT_NE(hp::test::refusalOf([&] { hp::Renderer r(*ctx, s); }).find("otherColors holds at most 7 formats, got 8"),
            std::string::npos);
  s.formats.otherColors = {VK_FORMAT_BC1_RGB_UNORM_BLOCK};  // a format no device attaches
  EXPECT_NE(hp::test::refusalOf([&] { hp::Renderer r(*ctx, s); }).find("is not a colour attachment on"),
            std::string::npos);
}

// RendererSettings::velocityOutput: the composite writes the hair's motion, scaled and offset, into the
// application's velocity attachment where the hair covers a pixel by more than minCoverage (0.3 of 3,000
// strands' hair), and leaves the
// other pixels and the other attachments as they were. The previous camera is shifted by (+3, -2) pixels, so
// every hair pixel moves by (-3, +2) (tests/render/motion_vectors_test.cpp); with scale (0.5, -0.25) and
// offset (1, 1) the attachment reads (-0.5, 0.5) there. The velocity attachment at colour location 1, 2, or 3
// after a slot the rendering leaves unused (three of the compiled variants), and an RGBA16F one whose last two
// channels must keep the engine's values, with 1 and 4 samples. (With 4 samples the test's coverage is
// Renderer::rasterCoverage, the same mean over the samples of the two layers that the shader computes.)
TEST_F(VulkanTest, VelocityOutputWritesTheHairsMotionWhereItCoversEnough) {
  hp::View view = hp::test::smallFrontView();
  glm::mat4 shift(1.0f);
  shift[3][0] = 2.0f * 3.0f / hp::test::kSmallWidth;
  shift[3][1] = -2.0f * -2.0f / hp::test::kSmallHeight;
  view.previousViewProj = shift * view.camera.proj * view.camera.view;
  const glm::vec2 expected(-3.0f * 0.5f + 1.0f, 2.0f * -0.25f + 1.0f), clear(3.0f, -2.0f);
  constexpr float kMinCoverage = 0.3f;
  const VkFormat normalFormat = kOthers[1];
  struct Order {
    std::vector<VkFormat> others;
    VkFormat velocity;
  };
  const std::vector<Order> orders = {{{kOthers[0], normalFormat}, kOthers[0]},
                                     {{normalFormat, kOthers[0]}, kOthers[0]},
                                     {{VK_FORMAT_UNDEFINED, normalFormat, kOthers[0]}, kOthers[0]},
                                     {{kWideVelocity, normalFormat}, kWideVelocity}};
  for (const VkSampleCountFlagBits samples : {VK_SAMPLE_COUNT_1_BIT, VK_SAMPLE_COUNT_4_BIT})
  for (const auto& [others, velocityFormat] : orders) {
    const auto at = [&](VkFormat f) { return std::size_t(std::find(others.begin(), others.end(), f) - others.begin()); };
    const int velocityIndex = int(at(velocityFormat));
    const std::size_t texelBytes = velocityFormat == kWideVelocity ? 8 : 4;
    SCOPED_TRACE(std::to_string(int(samples)) + " sample(s), velocity attachment otherColors[" +
                 std::to_string(velocityIndex) + "] of " + std::to_string(others.size()));
    hp::RendererSettings s = frameSettings(hp::RasterMode::Compute, true, samples);
    s.formats.otherColors = others;
    s.motionVectors = true;
    s.velocityOutput = {velocityIndex, 0.5f, -0.25f, 1.0f, 1.0f, kMinCoverage};
    std::vector<float> coverage;
    const auto frame = drawFrame(*ctx, s, view, &coverage, 3000);
    const std::vector<std::byte>& velocity = frame[1 + std::size_t(velocityIndex)];
    const std::vector<std::byte>& normal = frame[1 + at(normalFormat)];
    std::size_t covered = 0, uncovered = 0, wrongCovered = 0, wrongUncovered = 0;
    float worst = 0.0f;
    for (std::size_t p = 0; p < coverage.size(); ++p) {
      const glm::vec2 v = velocityAt(velocity, p, texelBytes);
      // Within half-float rounding of the threshold either answer is right.
      if (coverage[p] > kMinCoverage + 0.002f) {
        ++covered;
        worst = std::max(worst, glm::length(v - expected));
        wrongCovered += glm::length(v - expected) > 0.03f;
      } else if (coverage[p] < kMinCoverage - 0.002f) {
        ++uncovered;
        wrongUncovered += v != clear;
      }
    }
    std::cout << "velocity: " << covered << " pixels covered (largest error " << worst << "), " << uncovered
              << " not; written wrongly " << wrongCovered << ", changed where not covered " << wrongUncovered << "\n";
    EXPECT_GT(covered, std::size_t(hp::test::kSmallWidth) * hp::test::kSmallHeight / 20);
    EXPECT_GT(uncovered, covered);
    EXPECT_EQ(wrongCovered, 0u);
    EXPECT_EQ(wrongUncovered, 0u);
    EXPECT_EQ(texelsChanged(normal, kNormalClear, 4), 0u);
    if (velocityFormat == kWideVelocity) {  // the engine's blue and alpha, in every texel
      std::size_t blueAlphaChanged = 0;
      for (std::size_t p = 0; p < coverage.size(); ++p)
        blueAlphaChanged += std::memcmp(velocity.data() + p * 8 + 4, kWideVelocityBlueAlpha, 4) != 0;
      EXPECT_EQ(blueAlphaChanged, 0u);
    }
  }
}

TEST_F(VulkanTest, VelocityOutputIsRefusedByField) {
  hp::RendererSettings s = frameSettings(hp::RasterMode::Compute, true, VK_SAMPLE_COUNT_1_BIT);
  s.motionVectors = true;
  const auto refusal = [&](const hp::RendererSettings& settings) {
    return hp::test::refusalOf([&] { hp::Renderer r(*ctx, settings); });
  };
  s.velocityOutput.attachment = 2;
  EXPECT_NE(refusal(s).find("RendererSettings.velocityOutput.attachment must be -1 (none) or an index into "
                            "formats.otherColors (2 of them), got 2"), std::string::npos);
  s.velocityOutput.attachment = 0;
  s.motionVectors = false;
  EXPECT_NE(refusal(s).find("velocityOutput.attachment needs RendererSettings.motionVectors"), std::string::npos);
  s.motionVectors = true;
  s.velocityOutput.scaleY = std::nanf("");
  EXPECT_NE(refusal(s).find("RendererSettings.velocityOutput.scaleY must be finite, got NaN"), std::string::npos);
  s.velocityOutput.scaleY = 1.0f;
  s.velocityOutput.minCoverage = 1.0f;  // nothing is covered by more than all of it
  EXPECT_NE(refusal(s).find("RendererSettings.velocityOutput.minCoverage must be in [0, 1), got 1"), std::string::npos);
  s.velocityOutput.minCoverage = 0.5f;
  s.formats.otherColors[0] = VK_FORMAT_R16G16_SINT;
  EXPECT_NE(refusal(s).find("formats.otherColors[0] is an integer format (VkFormat 82)"), std::string::npos);
  s.formats.otherColors[0] = VK_FORMAT_R8G8B8A8_SRGB;
  EXPECT_NE(refusal(s).find("formats.otherColors[0] is an SRGB format (VkFormat 43)"), std::string::npos);
  s.formats.otherColors[0] = VK_FORMAT_UNDEFINED;
  EXPECT_NE(refusal(s).find("formats.otherColors[0] is an unused slot (VK_FORMAT_UNDEFINED)"), std::string::npos);
  s.formats.otherColors[0] = VK_FORMAT_R16G16_SFLOAT;
  s.raster = hp::RasterMode::Graphics;
  EXPECT_NE(refusal(s).find("motionVectors needs the compute raster"), std::string::npos);
}
