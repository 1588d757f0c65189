// hairpipe's draws inside an application's rendering with more colour attachments than hairpipe writes
// (AttachmentFormats::otherColors: an engine's velocity and normal targets in its main pass): its pipelines
// match that rendering, leave every other attachment as the application cleared it, and draw the same first
// colour as in a rendering of that colour alone; with both rasters, under synchronization validation.
#include <gtest/gtest.h>

#include <cstring>
#include <iostream>
#include <functional>
#include <string>
#include <vector>

#include "engine/core/error.h"
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

// One frame of the small front view (500 strands) drawn into the application's colour, depth and, with
// `others`, its other colour attachments, of `samples` samples (multisampled: each colour resolved by the
// last rendering). Returns every colour attachment's bytes (resolved), the first colour first.
std::vector<std::vector<std::byte>> drawFrame(const hp::vk::Context& ctx, hp::RasterMode raster, bool others,
                                              VkSampleCountFlagBits samples) {
  hp::RendererSettings s;
  s.formats = {kColor, kDepth, samples};
  if (others) s.formats.otherColors = kOthers;
  s.raster = raster;
  s.opacity.resolution = 256;
  hp::Renderer renderer(ctx, s);
  auto hair = renderer.createInstance(hp::test::defaultHeadWithStrands(500), {});
  hp::HairInstance* one[] = {hair.get()};
  const bool msaa = samples != VK_SAMPLE_COUNT_1_BIT;
  std::vector<VkFormat> formats = {kColor};
  if (others) formats.insert(formats.end(), kOthers.begin(), kOthers.end());
  std::vector<hp::vk::Image> colors, resolved;
  for (std::size_t i = 0; i < formats.size(); ++i) {
    const std::string name = i == 0 ? "colour" : "other " + std::to_string(i);
    colors.push_back(attachmentImage(ctx, formats[i], VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, name, samples));
    if (msaa) resolved.push_back(attachmentImage(ctx, formats[i], VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT, name + " resolved"));
  }
  const hp::vk::Image depth = attachmentImage(ctx, kDepth, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT,
                                              "depth", samples);
  const bool compute = raster == hp::RasterMode::Compute;
  if (compute) renderer.setRasterTarget(depth.extent(), depth.view(), one);
  const hp::View view = hp::test::smallFrontView();
  hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    renderer.recordUpdate(cmd, 0, one);
    renderer.recordShadows(cmd, 0, hp::LightSpec{}, one);
    std::vector<VkRenderingAttachmentInfo> attachments;
    for (const hp::vk::Image& r : resolved)
      hp::vk::imageBarrier(ctx, cmd, r.handle(), VK_IMAGE_ASPECT_COLOR_BIT, hp::vk::ImageUse::Undefined,
                           hp::vk::ImageUse::ColorAttachment);
    for (std::size_t i = 0; i < colors.size(); ++i) {
      hp::vk::imageBarrier(ctx, cmd, colors[i].handle(), VK_IMAGE_ASPECT_COLOR_BIT, hp::vk::ImageUse::Undefined,
                           hp::vk::ImageUse::ColorAttachment);
      attachments.push_back(hp::vk::colorAttachment(colors[i].view(), VK_ATTACHMENT_LOAD_OP_CLEAR,
                                                    i == 0 ? VkClearColorValue{} : kOtherClears[i - 1]));
    }
    hp::vk::imageBarrier(ctx, cmd, depth.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, hp::vk::ImageUse::Undefined,
                         hp::vk::ImageUse::DepthAttachment);
    VkRenderingAttachmentInfo depthInfo = hp::vk::depthAttachment(depth.view(), VK_ATTACHMENT_LOAD_OP_CLEAR,
                                                                   VK_ATTACHMENT_STORE_OP_STORE);
    // The last rendering resolves each multisampled colour (the average of its samples).
    const auto resolveInLastRendering = [&] {
      for (std::size_t i = 0; i < resolved.size(); ++i) {
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
      for (hp::vk::Image& c : colors)
        hp::vk::imageBarrier(ctx, cmd, c.handle(), VK_IMAGE_ASPECT_COLOR_BIT, hp::vk::ImageUse::ColorAttachment,
                             hp::vk::ImageUse::ColorAttachment);
      for (VkRenderingAttachmentInfo& a : attachments) a.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
      depthInfo.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
      resolveInLastRendering();
      ctx.fn().vkCmdBeginRendering(cmd, &info);
      renderer.recordComposite(cmd, depth.extent());
      ctx.fn().vkCmdEndRendering(cmd);
    }
  }, "other colour attachments");
  std::vector<std::vector<std::byte>> bytes;
  for (const hp::vk::Image& c : msaa ? resolved : colors)
    bytes.push_back(hp::vk::readbackImage(ctx, c, hp::vk::ImageUse::ColorAttachment));
  return bytes;
}

// Texels of `bytes` that differ from the texel `clear` (texelBytes bytes).
std::size_t texelsChanged(const std::vector<std::byte>& bytes, const void* clear, std::size_t texelBytes) {
  std::size_t n = 0;
  for (std::size_t at = 0; at + texelBytes <= bytes.size(); at += texelBytes)
    n += std::memcmp(bytes.data() + at, clear, texelBytes) != 0;
  return n;
}
}  // namespace

// Single-sampled and with 4 samples (the default: the ribbons' sample masks, the composite's two draws).
TEST_F(VulkanTest, OtherColorAttachmentsAreLeftAsTheApplicationClearedThem) {
  for (const VkSampleCountFlagBits samples : {VK_SAMPLE_COUNT_1_BIT, VK_SAMPLE_COUNT_4_BIT})
  for (const hp::RasterMode raster : {hp::RasterMode::Graphics, hp::RasterMode::Compute}) {
    SCOPED_TRACE(std::string(raster == hp::RasterMode::Compute ? "compute raster, " : "graphics raster, ") +
                 std::to_string(int(samples)) + " sample(s)");
    const auto alone = drawFrame(*ctx, raster, false, samples);
    const auto withOthers = drawFrame(*ctx, raster, true, samples);
    ASSERT_EQ(withOthers.size(), 3u);
    // The first colour as drawn alone: the head and hair drawn over a tenth of the frame at least.
    const std::uint16_t background[4] = {};
    EXPECT_GT(texelsChanged(alone[0], background, 8), std::size_t(hp::test::kSmallWidth) * hp::test::kSmallHeight / 10);
    std::size_t apart = 0;
    for (std::size_t at = 0; at < alone[0].size(); at += 8)
      apart += std::memcmp(alone[0].data() + at, withOthers[0].data() + at, 8) != 0;
    // Graphics: the same pipelines' output; compute: its run-to-run order within a depth bin (0-22 texels of
    // 15,360 apart over four runs of both sample counts, lavapipe; the bound is ~4.5 times that).
    std::cout << "first colour, texels apart from the frame drawn without the others: " << apart << "\n";
    EXPECT_LE(apart, raster == hp::RasterMode::Compute ? std::size_t(100) : std::size_t(0));
    EXPECT_EQ(texelsChanged(withOthers[1], kVelocityClear, 4), 0u);
    EXPECT_EQ(texelsChanged(withOthers[2], kNormalClear, 4), 0u);
  }
}

TEST_F(VulkanTest, OtherColorAttachmentsAreRefusedByField) {
  hp::RendererSettings s;
  s.formats = {kColor, kDepth, VK_SAMPLE_COUNT_1_BIT};
  s.formats.otherColors = {VK_FORMAT_R16G16_SFLOAT, VK_FORMAT_D32_SFLOAT};
  EXPECT_NE(hp::test::refusalOf([&] { hp::Renderer r(*ctx, s); })
                .find("RendererSettings.formats.otherColors[1] must be a colour format, got VkFormat 126"),
            std::string::npos);
  s.formats.otherColors.assign(8, VK_FORMAT_R8G8B8A8_UNORM);
  EXPECT_NE(hp::test::refusalOf([&] { hp::Renderer r(*ctx, s); }).find("otherColors holds at most 7 formats, got 8"),
            std::string::npos);
  s.formats.otherColors = {VK_FORMAT_BC1_RGB_UNORM_BLOCK};  // a format no device attaches
  EXPECT_NE(hp::test::refusalOf([&] { hp::Renderer r(*ctx, s); }).find("is not a colour attachment on"),
            std::string::npos);
}
