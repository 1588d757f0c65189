#pragma once
// Contract: the single-head convenience over hp::Renderer + one hp::HairInstance (compute/renderer/renderer.h has
// the full contract), with its own frame counter, for tools, tests and applications with one head:
//   recordUpdate(cmd, motion)        outside rendering: simulate -> tessellate -> interpolate
//   recordPrepareDraw(cmd, view)     outside rendering: starts a new frame; bounds and the opacity shadow
//                                    maps (in hairpipe's own vkCmdBeginRendering on its own images)
//   recordDraw(cmd, view)            inside the application's vkCmdBeginRendering (attachments matching
//                                    settings.formats): head mesh, then (graphics raster) hair ribbons
// With the compute raster (settings.raster == Compute), after setRasterTarget(extent, depth) once:
//   recordDraw(cmd, view)            head mesh only; end the rendering, depth -> ImageUse::ComputeSampled
//   recordRaster(cmd, view)          outside rendering: the compute rasterizer into rasterImage()
//   recordComposite(cmd, extent)     inside a rendering of the same attachments: hair over the colour
// Frames in flight: at most settings.framesInFlight frames (counted by recordPrepareDraw) may be pending
// on the GPU when a new one is prepared. Errors as Renderer's: construction, setMaterial and an invalid
// view or motion throw hp::Error.
#include <memory>
#include <vector>

#include "compute/raster/strand_raster_pass.h"
#include "compute/renderer/hair_instance.h"
#include "compute/raster/composite_pass.h"
#include "compute/renderer/renderer.h"

namespace hp {
struct HairSystemSettings {
  SimulationParams simulation;
  HairMaterial material;
  LutMode lutMode = LutMode::Physical;
  compute::StrandOptions strands;
  bool drawHead = true;  // false: hair only (InstanceSettings::drawHead)
  hairpipe::LodSettings lod;
  GroomSettings groom;
  hairpipe::AttachmentFormats formats;
  render::LookSettings look;
  render::OpacitySettings opacity;
  std::uint32_t shadowedLights = 1;  // RendererSettings::shadowedLights: the lights that get shadow maps, [1, 4]
  bool motionVectors = false;        // RendererSettings::motionVectors (compute raster: rasterMotion)
  std::uint32_t framesInFlight = 2;
  // Graphics by default here: an embedding that only calls recordDraw keeps drawing hair. The compute
  // path (RenderSpec::raster auto resolves to it for the CLI) needs setRasterTarget/recordRaster/recordComposite.
  RasterMode raster = RasterMode::Graphics;
  compute::RasterSettings rasterSettings;
  ScalpInput scalp;  // InstanceSettings::scalp (a character clip's Bones)
};

struct DrawView {
  CameraMatrices camera;
  VkExtent2D extent{1, 1};
  std::vector<LightSpec> lights{LightSpec{}};  // validateLights; the first shadowed ones get the shadow slots
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

  // Compute raster only. Outside the frame loop: the Renderer's raster target for this extent and the
  // head's depth image view, of the settings' AttachmentFormats sample count (Renderer::setRasterTarget
  // with the one instance; a previous target is retired after its frames).
  void setRasterTarget(VkExtent2D extent, VkImageView depth);
  // After the head's recordDraw; the depth image in ImageUse::ComputeSampled. Leaves rasterImage() in
  // ImageUse::FragmentSampled.
  void recordRaster(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler = nullptr);
  void recordComposite(VkCommandBuffer cmd, VkExtent2D extent, vk::GpuProfiler* profiler = nullptr) const;
  RasterMode raster() const { return renderer_.raster(); }
  const HairSystemSettings& settings() const { return settings_; }
  const vk::Image& rasterImage() const { return renderer_.rasterImage(); }
  compute::RasterStats rasterStats() const { return renderer_.rasterStats(); }  // blocking readback
  std::vector<float> rasterCoverage() const { return renderer_.rasterCoverage(); }  // blocking readback
  std::vector<glm::vec2> rasterMotion() const { return renderer_.rasterMotion(); }  // blocking; motionVectors only

  // Between frames, with earlier frames possibly in flight: the old textures are retired, not idled on.
  void setMaterial(const HairMaterial& material, LutMode mode);
  void setLook(const render::LookSettings& look);
  void setGroom(const GroomSettings& groom);
  // A new density (interpolation topology): new strand buffers, and a raster target rebuilt for them (by the
  // next frame's first record call, once frames were recorded). Until a recordUpdate has computed the new
  // strands (needsUpdate), the frame's recordPrepareDraw refuses them.
  void setStrands(const InterpolationTopology& topology);
  bool needsUpdate() const { return !instance_->strandsComputed(); }

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
  HairSystemSettings settings_;
};
}  // namespace hp
