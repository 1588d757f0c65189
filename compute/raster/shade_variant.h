#pragma once
// Contract: the builds of the compute raster's shade pass (shaders/raster_shade.comp, raster_shade_ms.comp), one
// per ShadeVariant: the constants of shaders/hair_shading.glsl that a frame fixes, the light loop and the fibre.
// lavapipe runs both sides of every branch under a mask, so what a variant fixes is compiled out rather than
// skipped (the fixed fibre: ~20 ms of the default frame's 75 ms shade pass there; docs/PERFORMANCE.md).
// The run-time fibre's two builds (with and without the light loop) are made at construction; prepare() adds
// a fixed fibre's, outside the frame loop. get() never builds: a variant not prepared falls back to the
// run-time fibre with the same light loop (the same image, slower on lavapipe), so a change in the frame loop
// compiles nothing. One recording thread at a time, as for StrandRasterPass.
#include "hairpipe_volk.h"

#include <compare>
#include <cstdint>
#include <map>
#include <string>

#include "engine/vk/pipeline.h"
#include "shaders/shared/marschner.h"
#include "shaders/shared/render.h"

namespace hp::compute {
struct ShadeVariant {
  bool lightLoop = true;  // every light of the frame block in a loop; false: at most one (HAIR_LIGHT_LOOP 0)
  std::uint32_t fibre = gpu::HAIR_FIBRE_RUNTIME;  // HAIR_FIBRE: the model and scattering, or read at run time
  auto operator<=>(const ShadeVariant&) const = default;
};

// The variant that shades with this frame block and fibre parameter block exactly as the run-time form does.
ShadeVariant shadeVariantOf(const gpu::RenderFrame& frame, const gpu::MarschnerParams& params);

class ShadePipelines {
 public:
  // shader: the embedded shade shader's name; layout: the pass's chunk set layout; cache: may be null.
  ShadePipelines(const vk::Context& ctx, std::string shader, VkDescriptorSetLayout layout, VkPipelineCache cache);
  void prepare(const ShadeVariant& variant);
  bool prepared(const ShadeVariant& variant) const { return built_.contains(variant); }
  const vk::ComputePipeline& get(const ShadeVariant& variant) const;

 private:
  const vk::Context* ctx_;
  std::string shader_;
  VkDescriptorSetLayout layout_;
  VkPipelineCache cache_;
  std::map<ShadeVariant, vk::ComputePipeline> built_;
};
}  // namespace hp::compute
