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
                     const compute::RasterSettings& settings)
    : ctx(c),
      extent(e),
      frame(render::makeRenderFrame(camera, e, render::assignShadowSlots(std::span(&light, 1), 1), HairMaterial{}, look, strands.layout(),
                                    shadowsOff())),
      marschner(c, HairMaterial{}, LutMode::Float),
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
