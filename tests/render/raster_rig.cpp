#include "tests/render/raster_rig.h"

#include <cstring>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/packing.hpp>

#include "compute/raster/raster_shading.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "shaders/shared/raster.h"

namespace hp::test {
namespace {
render::OpacitySettings shadowsOff() {
  render::OpacitySettings s;
  s.enabled = false;
  return s;
}
}  // namespace

void uploadPixelStrands(const vk::Context& ctx, const compute::StrandBuffers& buffers, const CameraMatrices& camera,
                        VkExtent2D extent, const std::vector<PixelStrand>& strands) {
  const std::uint32_t q = buffers.layout().verticesPerStrand;
  std::vector<glm::vec4> positions, tangents;
  std::vector<gpu::StrandAttributes> attributes;
  for (std::size_t s = 0; s < strands.size(); ++s) {
    const PixelStrand& p = strands[s];
    const glm::vec3 a = worldAtPixel(camera, extent, p.from, p.depth);
    const glm::vec3 b = worldAtPixel(camera, extent, p.to, p.depth);
    for (std::uint32_t j = 0; j < q; ++j) {
      const float v = float(j) / float(q - 1);
      positions.emplace_back(glm::mix(a, b, v), v);
      tangents.emplace_back(a == b ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::normalize(b - a), 0.0f);
    }
    // The look's root width is one pixel at unit depth: the scale makes it widthPixels at this depth.
    attributes.push_back({0.5f, p.widthPixels * p.depth, p.colorScale, std::uint32_t(s)});
  }
  const auto& chunk = buffers.chunks().front();
  vk::upload<glm::vec4>(ctx, chunk.positions, positions, vk::BufferUse::ComputeRead);
  vk::upload<glm::vec4>(ctx, chunk.tangents, tangents, vk::BufferUse::ComputeRead);
  vk::upload<gpu::StrandAttributes>(ctx, chunk.attributes, attributes, vk::BufferUse::ComputeRead);
}

std::unique_ptr<compute::StrandBuffers> makePixelStrands(const vk::Context& ctx, const CameraMatrices& camera,
                                                         VkExtent2D extent, const std::vector<PixelStrand>& strands,
                                                         std::uint32_t verticesPerStrand) {
  compute::StrandOptions options;
  options.verticesPerStrand = verticesPerStrand;
  options.guidesOnly = true;
  auto buffers = std::make_unique<compute::StrandBuffers>(ctx, std::uint32_t(strands.size()), 2,
                                                          InterpolationTopology{}, options);
  uploadPixelStrands(ctx, *buffers, camera, extent, strands);
  return buffers;
}

CameraMatrices rigCamera(VkExtent2D extent, float fovY) {
  CameraMatrices c;
  c.fovY = fovY;
  c.proj = glm::perspectiveRH_ZO(fovY, float(extent.width) / float(extent.height), 0.1f, 10.0f);
  return c;
}

glm::vec3 worldAtPixel(const CameraMatrices& camera, VkExtent2D extent, glm::vec2 pixel, float depth) {
  const float tanHalf = std::tan(0.5f * camera.fovY);
  const float aspect = float(extent.width) / float(extent.height);
  const float nx = 2.0f * pixel.x / float(extent.width) - 1.0f;
  const float ny = 1.0f - 2.0f * pixel.y / float(extent.height);  // rows go down
  return {nx * depth * tanHalf * aspect, ny * depth * tanHalf, -depth};
}

float ndcDepth(const CameraMatrices& camera, float depth) {
  const glm::vec4 clip = camera.proj * glm::vec4(0.0f, 0.0f, -depth, 1.0f);
  return clip.z / clip.w;
}

RasterRig::RasterRig(const vk::Context& c, const compute::StrandBuffers& strands, VkExtent2D e,
                     const CameraMatrices& camera, const render::LookSettings& look, const LightSpec& light,
                     const compute::RasterSettings& settings, LutMode fibre)
    : ctx(c),
      extent(e),
      frame(render::makeRenderFrame(camera, e, render::assignShadowSlots(std::span(&light, 1), 1), HairMaterial{}, look, strands.layout(),
                                    shadowsOff())),
      marschner(c, HairMaterial{}, fibre),
      frameBlock(c, sizeof(gpu::RenderFrame), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                 vk::MemoryKind::DeviceLocal, "rig frame"),
      shadows(c, shadowsOff()),
      depth(c, {e.width, e.height, 1, VK_FORMAT_D32_SFLOAT,
                VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                VK_SAMPLE_COUNT_1_BIT, "rig head depth"}) {
  vk::uploadBytes(c, frameBlock, &frame, sizeof(frame), vk::BufferUse::ComputeRead);
  const compute::ShadingWriter shading = [this](const vk::DescriptorSet& set) {
    compute::writeRasterShading(set, frameBlock.handle(), marschner, shadows.inputs());
  };
  pass = std::make_unique<compute::StrandRasterPass>(c, strands, shading, e, settings);
  pass->setDepth(depth.view());
}

void RasterRig::run(float headNdcDepth, bool binOnly) {
  vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    // Uploads were transfers of earlier submissions; the rasterizer reads them in compute.
    vk::memoryBarrier(ctx, cmd, vk::BufferUse::TransferDst, vk::BufferUse::ComputeRead);
    vk::imageBarrier(ctx, cmd, shadows.image().handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampled,
                     vk::ImageUse::ComputeSampled, gpu::OPACITY_LAYERS);
    vk::imageBarrier(ctx, cmd, depth.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::Undefined,
                     vk::ImageUse::TransferDst);
    const VkClearDepthStencilValue clear{headNdcDepth, 0};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
    ctx.fn().vkCmdClearDepthStencilImage(cmd, depth.handle(), vk::imageLayout(vk::ImageUse::TransferDst), &clear, 1, &range);
    vk::imageBarrier(ctx, cmd, depth.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::TransferDst,
                     vk::ImageUse::ComputeSampled);
    if (binOnly)
      pass->recordBinning(cmd);
    else
      pass->record(cmd);
    vk::imageBarrier(ctx, cmd, shadows.image().handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ComputeSampled,
                     vk::ImageUse::FragmentSampled, gpu::OPACITY_LAYERS);
  }, "raster rig");
}

void RasterRig::rerunFine(std::span<const compute::ShadeVariant> shading) {
  vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    vk::imageBarrier(ctx, cmd, shadows.image().handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampled,
                     vk::ImageUse::ComputeSampled, gpu::OPACITY_LAYERS);
    for (const vk::Image* image : {&pass->output(), &pass->nearOutput(), &pass->nearMask(), &pass->motionOutput()})
      vk::imageBarrier(ctx, cmd, image->handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampled,
                       vk::ImageUse::ComputeStorageWrite);
    pass->recordFine(cmd, nullptr, shading);
    vk::imageBarrier(ctx, cmd, shadows.image().handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ComputeSampled,
                     vk::ImageUse::FragmentSampled, gpu::OPACITY_LAYERS);
  }, "raster rig (fine again)");
}

std::vector<glm::vec4> RasterRig::image() const {
  const auto bytes = vk::readbackImage(ctx, pass->output(), vk::ImageUse::FragmentSampled);
  std::vector<glm::vec4> out(std::size_t(extent.width) * extent.height);
  for (std::size_t i = 0; i < out.size(); ++i) {
    std::uint16_t h[4];
    std::memcpy(h, bytes.data() + i * 8, 8);
    out[i] = {glm::unpackHalf1x16(h[0]), glm::unpackHalf1x16(h[1]), glm::unpackHalf1x16(h[2]), glm::unpackHalf1x16(h[3])};
  }
  return out;
}
}  // namespace hp::test
