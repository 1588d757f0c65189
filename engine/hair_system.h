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
//   recordDraw(cmd, view)            head mesh, then hair ribbons (depth test/write, coverage as a dithered sample mask)
// Stages it touches: COMPUTE_SHADER, COPY/CLEAR (vkCmdUpdateBuffer), VERTEX_SHADER, FRAGMENT_SHADER,
// early/late fragment tests and colour output; in the application's attachments only colour and depth. It never waits on a queue; the application keeps the
// HairSystem alive until the GPU has finished every command buffer it recorded into.
#include <memory>

#include "compute/bounds_pass.h"
#include "compute/interpolate_pass.h"
#include "compute/simulate_pass.h"
#include "compute/strand_buffers.h"
#include "compute/tessellate_pass.h"
#include "engine/hair/hair_asset.h"
#include "engine/hair/scene.h"
#include "engine/render/camera.h"
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
  LutMode lutMode = LutMode::Physical;
  compute::StrandOptions strands;
  render::AttachmentFormats formats;
  render::LookSettings look;
  render::OpacitySettings opacity;
};

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

  // Outside the frame loop, with the GPU done with this system: new material or LUT mode.
  void setMaterial(const HairMaterial& material, LutMode mode);

  SimulatePass& simulation() { return simulate_; }
  const compute::StrandBuffers& strands() const { return strands_; }
  const render::MarschnerTextures& marschner() const { return marschner_; }
  const compute::BoundsPass& bounds() const { return bounds_; }
  const render::OpacityPass& opacity() const { return opacity_; }
  const HairSystemSettings& settings() const { return settings_; }

 private:

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
