#pragma once
// Contract: the single-head convenience over hp::Renderer + one hp::HairInstance (engine/renderer.h has
// the full contract), with its own frame counter, for tools, tests and applications with one head:
//   recordUpdate(cmd, motion)        outside rendering: simulate -> tessellate -> interpolate
//   recordPrepareDraw(cmd, view)     outside rendering: starts a new frame; bounds and the opacity shadow
//                                    maps (in hairpipe's own vkCmdBeginRendering on its own images)
//   recordDraw(cmd, view)            inside the application's vkCmdBeginRendering (attachments matching
//                                    settings.formats): head mesh, then hair ribbons
// Frames in flight: at most settings.framesInFlight frames (counted by recordPrepareDraw) may be pending
// on the GPU when a new one is prepared. Errors as Renderer's: construction, setMaterial and an invalid
// view or motion throw hp::Error.
#include <memory>

#include "engine/hair_instance.h"
#include "engine/renderer.h"

namespace hp {
struct HairSystemSettings {
  SimulationParams simulation;
  HairMaterial material;
  LutMode lutMode = LutMode::Physical;
  compute::StrandOptions strands;
  render::AttachmentFormats formats;
  render::LookSettings look;
  render::OpacitySettings opacity;
  std::uint32_t framesInFlight = 2;
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
  void recordDraw(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler = nullptr);

  // Between frames, with earlier frames possibly in flight: the old textures are retired, not idled on.
  void setMaterial(const HairMaterial& material, LutMode mode) { instance_->setMaterial(material, mode); }

  SimulatePass& simulation() { return instance_->simulationForTools(); }
  const compute::StrandBuffers& strands() const { return instance_->strands(); }
  const render::MarschnerTextures& marschner() const { return instance_->marschner(); }
  const render::ShadowMaps& shadows() const { return renderer_.shadows(); }
  Renderer& renderer() { return renderer_; }
  HairInstance& instance() { return *instance_; }

 private:
  Renderer renderer_;
  std::unique_ptr<HairInstance> instance_;
  std::uint64_t frame_ = 0;
};
}  // namespace hp
