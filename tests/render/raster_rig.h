#pragma once
// Test support: the compute strand rasterizer over given strand buffers, outside a HairSystem, with a
// camera at the origin looking down -Z, the shading resources it binds (LUTs, frame block, opacity maps
// off), a head depth image cleared to a chosen NDC depth, and the hair image read back as floats.
#include <memory>
#include <vector>

#include "compute/raster/strand_raster_pass.h"
#include "compute/raster/frame_block.h"
#include "compute/raster/marschner_textures.h"
#include "compute/shadows/shadow_maps.h"

namespace hp::test {
struct RasterRig {
  RasterRig(const vk::Context& ctx, const compute::StrandBuffers& strands, VkExtent2D extent,
            const CameraMatrices& camera, const render::LookSettings& look, const LightSpec& light,
            const compute::RasterSettings& settings = {});

  // Shade, bin and (unless binOnly) fine-raster once with the head depth cleared to `headNdcDepth`.
  void run(float headNdcDepth = 1.0f, bool binOnly = false);
  std::vector<glm::vec4> image() const;  // RGBA (premultiplied radiance, alpha), rows top to bottom

  const vk::Context& ctx;
  VkExtent2D extent;
  gpu::RenderFrame frame;
  render::MarschnerTextures marschner;
  vk::Buffer frameBlock;
  render::ShadowMaps shadows;  // off: bound for the layout, never looked up
  vk::Image depth;
  std::unique_ptr<compute::StrandRasterPass> pass;
};

// A pinhole camera at the origin looking down -Z and the world point at pixel (x, y) and view depth d.
CameraMatrices rigCamera(VkExtent2D extent, float fovY);
glm::vec3 worldAtPixel(const CameraMatrices& camera, VkExtent2D extent, glm::vec2 pixel, float depth);
float ndcDepth(const CameraMatrices& camera, float depth);
}  // namespace hp::test
