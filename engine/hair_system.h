#pragma once
// Contract: the facade an application embeds: one head of hair, simulated, tessellated, interpolated
// and drawn on the device. It owns every pass and buffer and is the frame recorder: all barriers
// between its passes are recorded here, in one place. Per frame, into the application's command
// buffer, outside any render pass:
//   recordUpdate(cmd, motion)        simulate -> tessellate -> interpolate (compute)
//   recordPrepareDraw(cmd, view)     writes the frame block; bounds pass and the opacity shadow maps (the
//                                    latter in hairpipe's own vkCmdBeginRendering on its own images);
//                                    makes strands and maps visible to the draw
// and inside the application's vkCmdBeginRendering (attachments matching settings.formats):
//   recordDraw(cmd, view)            head mesh, then (graphics raster) hair ribbons (depth test/write,
//                                    coverage as a dithered sample mask)
// With the compute raster (raster() == RasterMode::Compute), after setRasterTarget(extent, depth) once:
//   recordDraw(cmd, view)            head mesh only; end the rendering, depth -> ImageUse::ComputeSampled
//   recordRaster(cmd)                outside rendering: the compute rasterizer into rasterImage()
//   recordComposite(cmd, extent)     inside a rendering of the same attachments: hair over the colour
// Stages it touches: COMPUTE_SHADER, COPY/CLEAR (vkCmdUpdateBuffer), VERTEX_SHADER, FRAGMENT_SHADER,
// early/late fragment tests and colour output; in the application's attachments only colour and depth. It never waits on a queue; the application keeps the
// HairSystem alive until the GPU has finished every command buffer it recorded into.
#include <memory>

#include "compute/bounds_pass.h"
#include "compute/interpolate_pass.h"
#include "compute/simulate_pass.h"
#include "compute/strand_buffers.h"
#include "compute/strand_raster_pass.h"
#include "compute/tessellate_pass.h"
#include "engine/hair/hair_asset.h"
#include "engine/hair/scene.h"
#include "engine/render/camera.h"
#include "engine/render/composite_pass.h"
#include "engine/render/frame_block.h"
#include "engine/render/head_pass.h"
#include "engine/render/marschner_textures.h"
#include "engine/render/opacity_pass.h"
#include "engine/render/strand_pass.h"
#include "engine/vk/profiler.h"

namespace hp {
struct HairSystemSettings {
  SimulationParams simulation;
  HairMaterial material;
  LutMode lutMode = LutMode::Float;
  compute::StrandOptions strands;
  render::AttachmentFormats formats;
  render::LookSettings look;
  render::OpacitySettings opacity;
  // Graphics by default here: an embedding that only calls recordDraw keeps drawing hair. The compute
  // path (RenderSpec::raster Auto resolves to it for the CLI) needs setRasterTarget/recordRaster/recordComposite.
  RasterMode raster = RasterMode::Graphics;
  compute::RasterSettings rasterSettings;
};

// Auto -> the path measured faster on this device type (docs/PERFORMANCE.md "Compute rasterizer").
RasterMode resolveRasterMode(RasterMode mode, VkPhysicalDeviceType type);

struct DrawView {
  CameraMatrices camera;
  VkExtent2D extent{1, 1};
  LightSpec light;
  glm::mat4 headToWorld{1.0f};
  bool lines = false;
};

class HairSystem {
 public:
  HairSystem(const vk::Context& ctx, const HairAsset& asset, const HairSystemSettings& settings,
             const glm::mat4& initialHead = glm::mat4(1.0f));

  void recordUpdate(VkCommandBuffer cmd, const HeadMotion& motion, vk::GpuProfiler* profiler = nullptr);
  void recordPrepareDraw(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler = nullptr);
  void recordDraw(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler = nullptr) const;

  // Compute raster only. Outside the frame loop: (re)builds the rasterizer for this extent (when it
  // changed) and binds the head's single-sample depth image view.
  void setRasterTarget(VkExtent2D extent, VkImageView depth);
  // After recordPrepareDraw and the head's recordDraw; the depth image in ImageUse::ComputeSampled.
  // Leaves rasterImage() in ImageUse::FragmentSampled.
  void recordRaster(VkCommandBuffer cmd, vk::GpuProfiler* profiler = nullptr) const;
  void recordComposite(VkCommandBuffer cmd, VkExtent2D extent, vk::GpuProfiler* profiler = nullptr) const;
  RasterMode raster() const { return raster_; }
  const vk::Image& rasterImage() const;
  compute::RasterStats rasterStats() const;  // blocking readback of the last frame's list statistics

  // Outside the frame loop, with the GPU done with this system: new material or LUT mode.
  void setMaterial(const HairMaterial& material, LutMode mode);

  SimulatePass& simulation() { return simulate_; }
  const compute::StrandBuffers& strands() const { return strands_; }
  const render::MarschnerTextures& marschner() const { return marschner_; }
  const compute::BoundsPass& bounds() const { return bounds_; }
  const render::OpacityPass& opacity() const { return opacity_; }
  const HairSystemSettings& settings() const { return settings_; }

 private:
  compute::ShadingWriter shadingWriter() const;
  void rebindShading();

  const vk::Context& ctx_;
  HairSystemSettings settings_;
  SimulatePass simulate_;
  compute::StrandBuffers strands_;
  compute::TessellatePass tessellate_;
  compute::InterpolatePass interpolate_;
  render::MarschnerTextures marschner_;
  vk::Buffer frameBlock_;
  compute::BoundsPass bounds_;
  render::OpacityPass opacity_;
  render::HeadPass head_;
  render::StrandPass strandPass_;
  RasterMode raster_;
  std::unique_ptr<compute::StrandRasterPass> rasterPass_;  // compute raster, after setRasterTarget
  std::unique_ptr<render::CompositePass> composite_;

};

// The shadow passes and the barriers around them, as recordPrepareDraw records them (public so tests
// can drive the passes over hand-made strands with the same synchronization). The strand positions'
// last ComputeWrite must already be made visible to VertexRead; this adds ComputeRead for the bounds.
// Leaves LightSpace in BufferUse::VertexRead and the maps in ImageUse::FragmentSampled.
compute::ShadowLight shadowLightOf(const LightSpec& light);
void recordShadowPasses(VkCommandBuffer cmd, const compute::BoundsPass& bounds, const render::OpacityPass& opacity,
                        const compute::ShadowLight& light, const compute::BoundsFraming& framing,
                        const glm::mat4& headToWorld, vk::GpuProfiler* profiler = nullptr);
}  // namespace hp
