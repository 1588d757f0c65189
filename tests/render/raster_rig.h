#pragma once
// Test support: the compute strand rasterizer over given strand buffers, outside a HairSystem, with a
// camera at the origin looking down -Z, the shading resources it binds (LUTs, frame block, opacity maps
// off), a head depth image cleared to a chosen NDC depth, and the hair image read back as floats.
#include <memory>
#include <span>
#include <vector>

#include "compute/raster/strand_raster_pass.h"
#include "compute/raster/frame_block.h"
#include "compute/raster/marschner_textures.h"
#include "compute/shadows/shadow_maps.h"

namespace hp::test {
struct RasterRig {
  RasterRig(const vk::Context& ctx, const compute::StrandBuffers& strands, VkExtent2D extent,
            const CameraMatrices& camera, const render::LookSettings& look, const LightSpec& light,
            const compute::RasterSettings& settings = {}, LutMode fibre = LutMode::Float);

  // Shade, bin and (unless binOnly) fine-raster once with the head depth cleared to `headNdcDepth`.
  void run(float headNdcDepth = 1.0f, bool binOnly = false);
  // Shade and fine-raster again over the lists of the last run(), with this shade variant (empty: the
  // run-time fibre, as run()).
  void rerunFine(std::span<const compute::ShadeVariant> shading);
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

// A straight strand in pixel space at one view depth, `widthPixels` wide (before the taper) under a look whose
// root width is one pixel at unit depth.
struct PixelStrand {
  glm::vec2 from, to;
  float depth = 1.0f;
  float widthPixels = 1.0f;
  float colorScale = 1.0f;
};
// Writes the strands, each as its buffers' Q vertices evenly along it, into buffers made for that many strands.
void uploadPixelStrands(const vk::Context& ctx, const compute::StrandBuffers& buffers, const CameraMatrices& camera,
                        VkExtent2D extent, const std::vector<PixelStrand>& strands);
// Guide-only buffers of Q vertices per strand holding the strands.
std::unique_ptr<compute::StrandBuffers> makePixelStrands(const vk::Context& ctx, const CameraMatrices& camera,
                                                         VkExtent2D extent, const std::vector<PixelStrand>& strands,
                                                         std::uint32_t verticesPerStrand);

// A pinhole camera at the origin looking down -Z and the world point at pixel (x, y) and view depth d.
CameraMatrices rigCamera(VkExtent2D extent, float fovY);
glm::vec3 worldAtPixel(const CameraMatrices& camera, VkExtent2D extent, glm::vec2 pixel, float depth);
float ndcDepth(const CameraMatrices& camera, float depth);
}  // namespace hp::test
