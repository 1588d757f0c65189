#pragma once
// Contract: hairpipe's own frame around a HairSystem, for the CLI, tests and benchmarks: it owns the
// offscreen targets (RenderTargets) and the tonemap pass, and records, into the caller's command
// buffer after HairSystem::recordPrepareDraw: clear, head + hair with MSAA into linear HDR, resolve,
// tonemap to sRGB. readDisplay() then returns the image (blocking; outside the frame loop).
#include <functional>
#include <vector>

#include "engine/hair_system.h"
#include "engine/render/render_targets.h"
#include "engine/render/tonemap_pass.h"

namespace hp::render {
class OffscreenRenderer {
 public:
  OffscreenRenderer(const vk::Context& ctx, std::uint32_t width, std::uint32_t height, std::uint32_t msaa);
  AttachmentFormats formats() const;
  VkExtent2D extent() const { return targets_.extent(); }

  void record(VkCommandBuffer cmd, HairSystem& hair, const DrawView& view, float exposure,
              vk::GpuProfiler* profiler = nullptr) const;
  // The same frame with any draws (a Renderer's instances) inside the rendering.
  void record(VkCommandBuffer cmd, const std::function<void(VkCommandBuffer)>& draws, float exposure,
              vk::GpuProfiler* profiler = nullptr) const;
  // RGBA8, sRGB-encoded, rows top to bottom. Waits for the queue through a one-shot readback.
  std::vector<std::uint8_t> readDisplay() const;

 private:
  void recordScene(VkCommandBuffer cmd, const std::function<void(VkCommandBuffer)>& draws) const;
  void recordTonemap(VkCommandBuffer cmd, float exposure) const;
  const vk::Image& hdrInput() const { return targets_.resolved ? targets_.resolved : targets_.hdr; }

  const vk::Context& ctx_;
  RenderTargets targets_;
  TonemapPass tonemap_;
};
}  // namespace hp::render
