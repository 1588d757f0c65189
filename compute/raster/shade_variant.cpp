#include "compute/raster/shade_variant.h"

#include <utility>

#include "shaders/shared/raster.h"

namespace hp::compute {
namespace {
std::string fibreName(std::uint32_t fibre) {
  if (fibre == gpu::HAIR_FIBRE_RUNTIME) return "any fibre";
  std::string name;
  switch (fibre & gpu::HAIR_FIBRE_MODE_MASK) {
    case gpu::MARSCHNER_MODE_DIRECT: name = "direct"; break;
    case gpu::MARSCHNER_MODE_LUT_PAPER: name = "paper"; break;
    case gpu::MARSCHNER_MODE_LUT_FLOAT: name = "float"; break;
    default: name = "physical"; break;
  }
  return name + ((fibre & gpu::HAIR_FIBRE_DUAL) != 0 ? ", dual" : "");
}
}  // namespace

ShadeVariant shadeVariantOf(const gpu::RenderFrame& frame, const gpu::MarschnerParams& params) {
  return {frame.lightCount.x > 1, gpu::hairFibre(params.control.x, frame.options.z == gpu::RENDER_SCATTERING_DUAL)};
}

ShadePipelines::ShadePipelines(const vk::Context& ctx, std::string shader, VkDescriptorSetLayout layout,
                               VkPipelineCache cache)
    : ctx_(&ctx), shader_(std::move(shader)), layout_(layout), cache_(cache) {
  prepare({true, gpu::HAIR_FIBRE_RUNTIME});
  prepare({false, gpu::HAIR_FIBRE_RUNTIME});
}

void ShadePipelines::prepare(const ShadeVariant& variant) {
  if (built_.contains(variant)) return;
  // constant_id 0: HAIR_LIGHT_LOOP, 1: HAIR_FIBRE (shaders/hair_shading.glsl).
  const std::string name = "raster shade (" + std::string(variant.lightLoop ? "light loop" : "one light") + ", " +
                           fibreName(variant.fibre) + ")";
  built_.emplace(variant, vk::ComputePipeline(*ctx_, shader_, gpu::RASTER_WORKGROUP_SIZE, {layout_}, 0, name,
                                              {variant.lightLoop ? 1u : 0u, variant.fibre}, cache_));
}

const vk::ComputePipeline& ShadePipelines::get(const ShadeVariant& variant) const {
  const auto it = built_.find(variant);
  return it != built_.end() ? it->second : built_.at({variant.lightLoop, gpu::HAIR_FIBRE_RUNTIME});
}
}  // namespace hp::compute
