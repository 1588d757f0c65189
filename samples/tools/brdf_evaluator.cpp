#include "samples/tools/brdf_evaluator.h"

#include <algorithm>
#include <string>

#include "engine/core/error.h"
#include "compute/raster/marschner_textures.h"
#include "engine/core/shading/marschner_gpu.h"
#include "engine/vk/buffer.h"
#include "engine/vk/context.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "shaders/shared/brdf_eval.h"

namespace hp::render {
namespace {
const vk::Binding kBindings[] = {
    {gpu::BRDF_EVAL_BINDING_INPUT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::BRDF_EVAL_BINDING_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::BRDF_EVAL_BINDING_PARAMS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::BRDF_EVAL_BINDING_M, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::BRDF_EVAL_BINDING_N0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::BRDF_EVAL_BINDING_N1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_COMPUTE_BIT},
};

// The input row (48 bytes) is the larger of the two bindings, so it decides the storage-range limit.
std::uint32_t chunkRows(const vk::Context& ctx, std::uint32_t requested) {
  if (requested == 0) throw Error("BrdfEvaluator: rows per chunk must be at least 1");
  const std::uint64_t byRange = ctx.properties().limits.maxStorageBufferRange / sizeof(gpu::BrdfEvalInput);
  if (byRange == 0) throw Error("BrdfEvaluator: maxStorageBufferRange is smaller than one input row");
  return static_cast<std::uint32_t>(std::min<std::uint64_t>(requested, byRange));
}
}  // namespace

BrdfEvaluator::BrdfEvaluator(const vk::Context& ctx, std::uint32_t maxRowsPerChunk)
    : ctx_(ctx),
      rowsPerChunk_(chunkRows(ctx, maxRowsPerChunk)),
      set_(ctx, kBindings, "brdf_eval set"),
      pipeline_(ctx, "brdf_eval.comp", gpu::BRDF_EVAL_WORKGROUP_SIZE, {set_.layout()}, sizeof(gpu::BrdfEvalPush),
                "brdf_eval") {}

std::vector<glm::vec3> BrdfEvaluator::evaluate(const MarschnerTextures& textures, std::span<const BrdfQuery> queries) {
  std::vector<glm::vec3> result(queries.size());
  if (queries.empty()) return result;
  const std::uint32_t capacity =
      static_cast<std::uint32_t>(std::min<std::size_t>(queries.size(), rowsPerChunk_));
  vk::Buffer input(ctx_, VkDeviceSize(capacity) * sizeof(gpu::BrdfEvalInput),
                   VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryKind::DeviceLocal,
                   "brdf_eval input");
  vk::Buffer output(ctx_, VkDeviceSize(capacity) * sizeof(glm::vec4),
                    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT, vk::MemoryKind::DeviceLocal,
                    "brdf_eval output");
  set_.writeStorageBuffer(gpu::BRDF_EVAL_BINDING_INPUT, input.handle());
  set_.writeStorageBuffer(gpu::BRDF_EVAL_BINDING_OUTPUT, output.handle());
  textures.writeDescriptors(set_, gpu::BRDF_EVAL_BINDING_PARAMS, gpu::BRDF_EVAL_BINDING_M, gpu::BRDF_EVAL_BINDING_N0,
                            gpu::BRDF_EVAL_BINDING_N1);
  const std::uint32_t mode = gpuModeOf(textures.mode());

  std::vector<gpu::BrdfEvalInput> rows;
  rows.reserve(capacity);
  for (std::size_t first = 0; first < queries.size(); first += capacity) {
    const auto count = static_cast<std::uint32_t>(std::min<std::size_t>(capacity, queries.size() - first));
    rows.clear();
    for (std::uint32_t i = 0; i < count; ++i) {
      const BrdfQuery& q = queries[first + i];
      rows.push_back({glm::vec4(q.L, 0.0f), glm::vec4(q.V, q.roughness), glm::vec4(q.T, q.tilt)});
    }
    // Each step below is fence-waited, so reusing the two buffers across chunks is race-free.
    vk::upload<gpu::BrdfEvalInput>(ctx_, input, rows, vk::BufferUse::ComputeRead);
    vk::submitAndWait(ctx_, [&](VkCommandBuffer cmd) {
      pipeline_.bind(cmd, set_.set());
      pipeline_.push(cmd, gpu::BrdfEvalPush{glm::uvec4(count, mode, 0u, 0u)});
      pipeline_.dispatch(cmd, count);
    }, "brdf_eval " + std::to_string(count) + " rows");
    std::vector<glm::vec4> s = vk::readback<glm::vec4>(ctx_, output, vk::BufferUse::ComputeWrite, count);
    for (std::uint32_t i = 0; i < count; ++i) result[first + i] = glm::vec3(s[i]);
  }
  return result;
}

std::vector<glm::vec3> evaluateBrdfOnDevice(const vk::Context& ctx, const MarschnerTextures& textures,
                                            std::span<const BrdfQuery> queries) {
  BrdfEvaluator evaluator(ctx);
  return evaluator.evaluate(textures, queries);
}
}  // namespace hp::render
