#include "compute/strands/hair_grid_pass.h"

#include <string>

#include "engine/core/error.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/transfer.h"

namespace hp {
namespace {
const vk::Binding kHairGridBindings[] = {
    {gpu::GRID_BINDING_POSITIONS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::GRID_BINDING_PREVIOUS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::GRID_BINDING_ACCUM, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::GRID_BINDING_CELLS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::GRID_BINDING_PEAK, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
};
constexpr VkBufferUsageFlags kHairGridUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

VkDeviceSize checkedBytes(const vk::Context& ctx, std::uint64_t bytes) {
  if (bytes > ctx.properties().limits.maxStorageBufferRange)
    throw Error("hair grid: " + std::to_string(bytes) + " bytes, past this device's maxStorageBufferRange of " +
                std::to_string(ctx.properties().limits.maxStorageBufferRange) + " (lower gridResolution)");
  return bytes;
}

double restMean(std::span<const glm::vec4> rest, std::uint32_t particlesPerGuide, const HairGridLayout& layout) {
  return weightedMeanDensity(splatHairGrid(freeParticles(rest, particlesPerGuide), layout));
}
}  // namespace

HairGridPass::HairGridPass(const vk::Context& ctx, std::span<const glm::vec4> rest, std::uint32_t particlesPerGuide,
                           std::uint32_t resolution, float pearlRadius, const vk::Buffer& positions,
                           const vk::Buffer& previous, vk::PipelineLibrary* library)
    : ctx_(ctx),
      layout_(hairGridLayout(rest, particlesPerGuide, resolution, pearlRadius)),
      particles_(std::uint32_t(rest.size())),
      particlesPerGuide_(particlesPerGuide),
      restMean_(restMean(rest, particlesPerGuide, layout_)),
      fixedPoint_(hairGridFixedPoint(rest.size())) {
  const std::uint64_t cells = layout_.cellCount();
  accum_ = vk::Buffer(ctx, checkedBytes(ctx, cells * gpu::GRID_ACCUM_INTS * 4), kHairGridUsage, vk::MemoryKind::DeviceLocal,
                      "hair grid accumulation");
  cells_ = vk::Buffer(ctx, checkedBytes(ctx, cells * gpu::GRID_CELL_VEC4S * 16), kHairGridUsage, vk::MemoryKind::DeviceLocal,
                      "hair grid cells");
  peak_ = vk::Buffer(ctx, 4, kHairGridUsage, vk::MemoryKind::DeviceLocal, "hair grid peak density");
  set_ = vk::DescriptorSet(ctx, kHairGridBindings, "hair grid");
  set_.writeStorageBuffer(gpu::GRID_BINDING_POSITIONS, positions.handle());
  set_.writeStorageBuffer(gpu::GRID_BINDING_PREVIOUS, previous.handle());
  set_.writeStorageBuffer(gpu::GRID_BINDING_ACCUM, accum_.handle());
  set_.writeStorageBuffer(gpu::GRID_BINDING_CELLS, cells_.handle());
  set_.writeStorageBuffer(gpu::GRID_BINDING_PEAK, peak_.handle());
  splat_ = vk::makeComputePipeline(ctx, library, "hair_grid_splat.comp", gpu::GRID_WORKGROUP_SIZE, {set_.layout()},
                                   sizeof(gpu::GridParams), "hair grid splat");
  resolve_ = vk::makeComputePipeline(ctx, library, "hair_grid_resolve.comp", gpu::GRID_WORKGROUP_SIZE, {set_.layout()},
                                     sizeof(gpu::GridParams), "hair grid resolve");
  vk::upload<std::uint32_t>(ctx, peak_, std::vector<std::uint32_t>{0u}, vk::BufferUse::ComputeWrite);  // no peak yet
}

void HairGridPass::record(VkCommandBuffer cmd, const glm::mat4& worldToHead, double substep, double maxSpeed,
                          double target) {
  gpu::GridParams p{};
  p.worldToGrid = worldToHead;
  p.originCell = glm::vec4(layout_.origin, layout_.cellSize);
  p.dims = glm::uvec4(layout_.dims, particles_);
  p.fixedPoint = glm::vec4(fixedPoint_, 1.0f / fixedPoint_, float(1.0 / substep), float(maxSpeed));
  p.density = glm::vec4(restMean_ > 0.0 ? float(1.0 / restMean_) : 0.0f, float(target), float(particlesPerGuide_), 0.0f);
  const auto& fn = ctx_.fn();
  // Global barriers: four a frame whatever the buffers. The last frame's resolve read the sums and its
  // simulation read the cells; the splat reads the particles the simulation writes next.
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::TransferDst);
  fn.vkCmdFillBuffer(cmd, accum_.handle(), 0, VK_WHOLE_SIZE, 0u);
  fn.vkCmdFillBuffer(cmd, peak_.handle(), 0, VK_WHOLE_SIZE, 0u);
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::TransferDst, vk::BufferUse::ComputeWrite);
  splat_->bind(cmd, set_.set());
  splat_->push(cmd, p);
  splat_->dispatch(cmd, particles_);
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  resolve_->bind(cmd, set_.set());
  resolve_->push(cmd, p);
  resolve_->dispatch(cmd, layout_.cellCount());
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
}
}  // namespace hp
