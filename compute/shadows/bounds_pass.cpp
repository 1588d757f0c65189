#include "compute/shadows/bounds_pass.h"

#include <cmath>
#include <string>


namespace hp::compute {
namespace {
const vk::Binding kBoundsBindings[] = {
    {gpu::BOUNDS_BINDING_POSITIONS, vk::kStorage, vk::kCompute},
    {gpu::BOUNDS_BINDING_LIGHT, vk::kStorage, vk::kCompute},
};
constexpr float kBig = 3.0e38f;  // the shader's empty-reduction value
}  // namespace

glm::mat3 lightBasisRows(const glm::vec3& towardLight) {
  const glm::vec3 z = glm::normalize(towardLight);
  const glm::vec3 up = std::abs(z.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  const glm::vec3 x = glm::normalize(glm::cross(up, z));
  const glm::vec3 y = glm::cross(z, x);
  return glm::transpose(glm::mat3(x, y, z));  // rows x, y, z
}

ShadowLight ShadowLight::makeSpot(const glm::vec3& position, const glm::vec3& towardLight, float coneRadians) {
  ShadowLight l(towardLight);
  l.spot = true;
  l.position = position;
  l.coneRadians = coneRadians;
  return l;
}

gpu::LightSpace initialLightSpace() {
  gpu::LightSpace l{};
  l.viewProj = glm::mat4(1.0f);
  l.depthRange = glm::vec4(0.0f, 1.0f, 1.0f / gpu::OPACITY_SLICES, float(gpu::OPACITY_SLICES));
  l.extent = glm::vec4(-1, -1, 1, 1);
  l.minBits = glm::uvec4(gpu::orderedFromFloat(kBig));
  l.maxBits = glm::uvec4(gpu::orderedFromFloat(-kBig));
  return l;
}

BoundsPass::BoundsPass(const vk::Context& ctx, const StrandBuffers& strands, const vk::Buffer& lightSpace,
                       vk::PipelineLibrary* library)
    : ctx_(&ctx),
      lightSpace_(&lightSpace),
      layoutSet_(ctx, kBoundsBindings, "bounds layout"),
      pipeline_(vk::makeComputePipeline(ctx, library, "bounds.comp", gpu::BOUNDS_WORKGROUP_SIZE,
                                        {layoutSet_.layout()}, sizeof(gpu::BoundsPush), "bounds")) {
  bind(strands);
}

void BoundsPass::bind(const StrandBuffers& strands) {
  std::vector<Chunk> chunks;
  for (const StrandChunk& c : strands.chunks()) {
    Chunk chunk{vk::DescriptorSet(*ctx_, kBoundsBindings, "bounds [chunk " + std::to_string(chunks.size()) + "]"),
                c.range.strandCount * strands.layout().verticesPerStrand};
    chunk.set.writeStorageBuffer(gpu::BOUNDS_BINDING_POSITIONS, c.positions.handle());
    chunk.set.writeStorageBuffer(gpu::BOUNDS_BINDING_LIGHT, lightSpace_->handle());
    chunks.push_back(std::move(chunk));
  }
  chunks_ = std::move(chunks);
}

gpu::BoundsPush BoundsPass::push(const ShadowLight& light) const {
  const glm::mat3 rows = glm::transpose(lightBasisRows(light.towardLight));  // columns = rows of the basis
  gpu::BoundsPush p{};
  p.slot = light.slot;
  p.row0 = glm::vec4(rows[0], 0.0f);
  p.row1 = glm::vec4(rows[1], 0.0f);
  p.row2 = glm::vec4(rows[2], 0.0f);
  if (light.spot) {
    p.perspective = 1;
    p.tanCone = std::tan(light.coneRadians);
    p.nearLimit = kSpotNearLimit;
    p.origin = glm::vec4(light.position, 0.0f);
  }
  return p;
}

void BoundsPass::recordReduce(VkCommandBuffer cmd, const ShadowLight& light) const {
  gpu::BoundsPush p = push(light);
  p.mode = gpu::BOUNDS_MODE_REDUCE;
  for (const Chunk& c : chunks_) {
    p.vertexCount = c.vertexCount;
    pipeline_->bind(cmd, c.set.set());
    pipeline_->push(cmd, p);
    pipeline_->dispatch(cmd, (c.vertexCount + gpu::BOUNDS_VERTICES_PER_THREAD - 1) / gpu::BOUNDS_VERTICES_PER_THREAD);
  }
}

void BoundsPass::recordFinalize(VkCommandBuffer cmd, const ShadowLight& light, const BoundsFraming& f) const {
  gpu::BoundsPush p = push(light);
  p.mode = gpu::BOUNDS_MODE_FINALIZE;
  p.marginWorld = f.marginWorld;
  p.marginTexels = f.marginTexels;
  p.resolution = f.resolution;
  pipeline_->bind(cmd, chunks_.front().set.set());
  pipeline_->push(cmd, p);
  pipeline_->dispatch(cmd, 1);
}
}  // namespace hp::compute
