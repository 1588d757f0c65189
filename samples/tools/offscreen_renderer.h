#pragma once
// Contract: hairpipe's own frame around a HairSystem, for the CLI, tests and benchmarks: it owns the
// offscreen targets (RenderTargets) and the tonemap pass, and records, into the caller's command
// buffer after HairSystem::recordPrepareDraw: clear, head + hair with MSAA into linear HDR, resolve,
// tonemap to sRGB. readDisplay() then returns the image (blocking; outside the frame loop).
// With RasterMode::Compute a HairSystem frame is: head (MSAA), the compute rasterizer reading the head's
// depth samples (hair coverage is analytic; the head's samples antialias its edges over the hair), the
// composite of the hair layers over the colour, resolve, tonemap. attach(hair) once binds the
// rasterizer's target.
#include <functional>
#include <memory>
#include <span>
#include <vector>

#include "samples/tools/hair_system.h"
#include "samples/tools/linear_image.h"
#include "samples/tools/render_targets.h"
#include "samples/tools/tonemap_pass.h"

namespace hp::render {
class OffscreenRenderer {
 public:
  // reversedDepth: the depth cleared to 0 and formats() saying so, as a reversed-Z application's (its views'
  // projections must then be reversed too).
  OffscreenRenderer(const vk::Context& ctx, std::uint32_t width, std::uint32_t height, std::uint32_t msaa,
                    RasterMode raster = RasterMode::Graphics, bool reversedDepth = false);
  RasterMode raster() const { return raster_; }
  // Compute raster: binds this renderer's extent and depth to the hair's rasterizer (outside the frame loop).
  void attach(HairSystem& hair) const;
  // The same for a Renderer's instances (the middleware API; the Renderer's raster mode must be compute).
  void attach(Renderer& renderer, std::span<HairInstance* const> instances) const;
  // A raster target of its own on the Renderer for this renderer's extent and depth (another view of a frame).
  std::shared_ptr<RasterTarget> createTarget(Renderer& renderer, std::span<HairInstance* const> instances) const;
  hairpipe::AttachmentFormats formats() const;
  VkExtent2D extent() const { return targets_.extent(); }
  // The sRGB image record() leaves in ImageUse::ColorAttachment (a window blits it to its swapchain).
  const vk::Image& display() const { return targets_.display; }

  void record(VkCommandBuffer cmd, HairSystem& hair, const DrawView& view, float exposure,
              vk::GpuProfiler* profiler = nullptr) const;
  // The same frame with any draws (a Renderer's instances) inside the rendering.
  void record(VkCommandBuffer cmd, const std::function<void(VkCommandBuffer)>& draws, float exposure,
              vk::GpuProfiler* profiler = nullptr) const;
  // Compute raster: a Renderer's frame `frame` of its attached instances (heads by recordDraw, then
  // recordRaster, recordComposite), after its recordShadows. `applicationDraws`, when given, records into
  // the heads' rendering before recordDraw: what an application draws first (its character), which the
  // heads and the hair are depth-tested against. `target`: one createTarget made (default: the Renderer's own).
  void record(VkCommandBuffer cmd, Renderer& renderer, std::uint64_t frame, const View& view,
              std::span<HairInstance* const> instances, float exposure, vk::GpuProfiler* profiler = nullptr,
              const std::function<void(VkCommandBuffer)>& applicationDraws = {}, RasterTarget* target = nullptr) const;
  // RGBA8, sRGB-encoded, rows top to bottom. Waits for the queue through a one-shot readback.
  std::vector<std::uint8_t> readDisplay() const;
  // The frame's linear HDR radiance before exposure and tonemap (RGB floats, rows top to bottom);
  // after record(), blocking like readDisplay().
  LinearImage readLinear() const;

 private:
  // Throws hp::Error naming `call` unless both this renderer and `renderer` use the compute raster.
  void requireCompute(const Renderer& renderer, const char* call) const;
  void recordScene(VkCommandBuffer cmd, const std::function<void(VkCommandBuffer)>& draws) const;
  // Compute raster: heads (drawHeads, inside a rendering), raster (outside, depth sampled), composite (in a
  // rendering timed as "composite pass" by the profiler, if any).
  using Record = std::function<void(VkCommandBuffer)>;
  void recordComputeScene(VkCommandBuffer cmd, const Record& drawHeads, const Record& raster,
                          const Record& composite, vk::GpuProfiler* profiler) const;
  void recordTonemap(VkCommandBuffer cmd, float exposure) const;
  // A frame's first use of the colour, depth and resolve targets: their old contents discarded.
  void discardTargets(VkCommandBuffer cmd) const;
  // With MSAA: the colour attachment resolves (average) into the resolve target, its samples discarded.
  void resolveInto(VkRenderingAttachmentInfo& color) const;
  const vk::Image& hdrInput() const { return targets_.resolved ? targets_.resolved : targets_.hdr; }

  // The depth attachment as the scene's renderings take it (cleared to the far plane of its convention).
  VkRenderingAttachmentInfo sceneDepth(VkAttachmentLoadOp load, VkAttachmentStoreOp store) const;

  const vk::Context& ctx_;
  RasterMode raster_;
  bool reversedDepth_;
  RenderTargets targets_;
  TonemapPass tonemap_;
};

// Channels [first, first + channels) of an RGBA16F image read back (rows top to bottom) as floats.
LinearImage rgbOfHalfRgba(const std::vector<std::byte>& bytes, VkExtent2D extent, std::uint32_t first,
                          std::uint32_t channels);
}  // namespace hp::render
