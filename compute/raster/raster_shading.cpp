#include "compute/raster/raster_shading.h"

#include "shaders/shared/render.h"

namespace hp::compute {
void writeRasterShading(const vk::DescriptorSet& set, VkBuffer frameBlock, const render::MarschnerTextures& marschner,
                        const render::ShadowInputs& shadows) {
  set.writeStorageBuffer(gpu::RENDER_BINDING_FRAME, frameBlock);
  marschner.writeDescriptors(set, gpu::RENDER_BINDING_MARSCHNER, gpu::RENDER_BINDING_LUT_M, gpu::RENDER_BINDING_LUT_N0,
                             gpu::RENDER_BINDING_LUT_N1);
  set.writeSampledImage(gpu::RENDER_BINDING_OPACITY, shadows.opacityView, shadows.sampler);
  set.writeStorageBuffer(gpu::RENDER_BINDING_LIGHT, shadows.lightSpace);
  set.writeSampledImage(gpu::RENDER_BINDING_HEAD_SHADOW, shadows.headShadowView, shadows.headShadowSampler);
}
}  // namespace hp::compute
