#include "compute/strands/simulate_pass.h"

#include <cstring>

#include "engine/core/error.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/transfer.h"

namespace hp {
namespace {
constexpr VkBufferUsageFlags kParticleUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

const vk::Binding kSimulateBindings[] = {
    {gpu::SIM_BINDING_FRAME, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::SIM_BINDING_POSITIONS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::SIM_BINDING_PREVIOUS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::SIM_BINDING_REST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::SIM_BINDING_ROOTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::SIM_BINDING_ROOTS_PREV, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::SIM_BINDING_BONES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::SIM_BINDING_SKIN, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::SIM_BINDING_SDF, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
    {gpu::SIM_BINDING_GRID, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_COMPUTE_BIT},
};

VkDeviceSize particleBytes(const vk::Context& ctx, const GuideSet& guides) {
  checkParticlesPerGuide(guides.particlesPerGuide, "simulation");
  if (guides.guideCount() == 0) throw Error("simulation: the asset has no guides");
  VkDeviceSize bytes = VkDeviceSize(guides.positions.size()) * sizeof(glm::vec4);
  if (bytes > ctx.properties().limits.maxStorageBufferRange)
    throw Error("simulation: " + std::to_string(guides.guideCount()) + " guides need " + std::to_string(bytes) +
                " bytes per particle buffer, past this device's maxStorageBufferRange of " +
                std::to_string(ctx.properties().limits.maxStorageBufferRange));
  return bytes;
}

glm::vec4 point(const glm::mat4& m, const glm::vec4& p) { return m * glm::vec4(glm::vec3(p), 1.0f); }
}  // namespace

std::vector<glm::vec4> guideRestPose(const GuideSet& guides) {
  std::vector<glm::vec4> rest(guides.positions.size());
  for (std::uint32_t g = 0; g < guides.guideCount(); ++g) {
    auto p = guides.guide(g);
    for (std::size_t i = 0; i < p.size(); ++i) {
      float len = i == 0 ? 0.0f : glm::length(p[i] - p[i - 1]);
      rest[std::size_t(g) * p.size() + i] = glm::vec4(p[i], len);
    }
  }
  return rest;
}

SimulatePass::SimulatePass(const vk::Context& ctx, const HairAsset& asset, const SimulationParams& params,
                           const glm::mat4& initialHead, vk::PipelineLibrary* library, const ScalpInput& scalp)
    : ctx_(ctx),
      params_(params),
      guideCount_(asset.guides.guideCount()),
      particlesPerGuide_(asset.guides.particlesPerGuide),
      rest_(guideRestPose(asset.guides)),
      scalp_(ctx, scalp, rest_, std::max(1u, asset.guides.particlesPerGuide), initialHead),
      sdf_(ctx, asset.sdf) {
  params_.validate();
  setColliders(asset.colliders);
  const VkDeviceSize bytes = particleBytes(ctx, asset.guides);
  positions_ = vk::Buffer(ctx, bytes, kParticleUsage, vk::MemoryKind::DeviceLocal, "guide positions");
  previous_ = vk::Buffer(ctx, bytes, kParticleUsage, vk::MemoryKind::DeviceLocal, "guide previous positions");
  restBuffer_ = vk::Buffer(ctx, bytes, kParticleUsage, vk::MemoryKind::DeviceLocal, "guide rest pose");
  frame_ = vk::Buffer(ctx, sizeof(gpu::SimFrame), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                      vk::MemoryKind::DeviceLocal, "simulation frame");
  grid_.emplace(ctx, rest_, particlesPerGuide_, params_.gridResolution, float(params_.pearlRadius), positions_, previous_,
                library);
  set_ = makeSet();
  static_assert(gpu::SIM_SPEC_PARTICLES == 0, "ComputePipeline numbers specialization constants from 0");
  pipeline_ = vk::makeComputePipeline(ctx, library, "simulate.comp", gpu::SIM_WORKGROUP_SIZE, {set_.layout()}, 0, "simulate",
                                  {particlesPerGuide_});
  vk::upload<glm::vec4>(ctx, restBuffer_, rest_, vk::BufferUse::ComputeRead);
  if (asset.character && asset.character->skinned() && asset.characterCollides) {
    const bool scalp = asset.head.scalp.size() == asset.character->positions.size();
    character_ = std::make_unique<CharacterPass>(ctx, *asset.character, scalp ? std::span<const float>(asset.head.scalp)
                                                                                : std::span<const float>(), sdf_, library);
  }
  reset(initialHead);
}

vk::DescriptorSet SimulatePass::makeSet() const {
  vk::DescriptorSet set(ctx_, kSimulateBindings, "simulate");
  set.writeStorageBuffer(gpu::SIM_BINDING_FRAME, frame_.handle());
  set.writeStorageBuffer(gpu::SIM_BINDING_POSITIONS, positions_.handle());
  set.writeStorageBuffer(gpu::SIM_BINDING_PREVIOUS, previous_.handle());
  set.writeStorageBuffer(gpu::SIM_BINDING_REST, restBuffer_.handle());
  scalp_.writeDescriptors(set);
  set.writeStorageBuffer(gpu::SIM_BINDING_SDF, sdf_.buffer().handle());
  set.writeStorageBuffer(gpu::SIM_BINDING_GRID, grid_->cells().handle());
  return set;
}

std::shared_ptr<vk::DescriptorSet> SimulatePass::setRootFrames(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize bytes) {
  const ScalpInput before = scalp_.input();
  scalp_.setRootFrames(buffer, offset, bytes);
  try {
    auto old = std::make_shared<vk::DescriptorSet>(makeSet());  // the new set, swapped in below
    std::swap(*old, set_);
    return old;
  } catch (...) {  // no set: the pass keeps reading the former buffer
    scalp_.setRootFrames(before.rootFrames, before.rootFramesOffset, before.rootFramesBytes);
    throw;
  }
}

void SimulatePass::setCharacterPose(std::span<const glm::mat4> bones) {
  if (!character_) throw Error("simulation: the asset has no skinned character mesh it collides with to pose");
  character_->setPose(bones);
}

void SimulatePass::setParams(const SimulationParams& params) {
  params.validate();
  if (params.gridResolution != params_.gridResolution)
    throw Error("simulation: gridResolution is fixed when the simulation is created (" +
                std::to_string(params_.gridResolution) + "), got " + std::to_string(params.gridResolution));
  params_ = params;
}

void SimulatePass::setColliders(std::span<const SphereCollider> spheres, std::span<const CapsuleCollider> capsules) {
  if (spheres.size() > gpu::SIM_MAX_COLLIDERS)
    throw Error("simulation: " + std::to_string(spheres.size()) + " colliders, at most " +
                std::to_string(gpu::SIM_MAX_COLLIDERS) + " are supported");
  if (capsules.size() > gpu::SIM_MAX_CAPSULES)
    throw Error("simulation: " + std::to_string(capsules.size()) + " capsule colliders, at most " +
                std::to_string(gpu::SIM_MAX_CAPSULES) + " are supported");
  for (const auto& c : spheres)
    if (!std::isfinite(c.radius) || c.radius < 0.0f || !std::isfinite(glm::length(c.center)))
      throw Error("simulation: a collider has a negative or non-finite radius or center");
  for (const auto& c : capsules)
    if (!std::isfinite(c.radius) || c.radius < 0.0f || !std::isfinite(glm::length(c.a)) ||
        !std::isfinite(glm::length(c.b)))
      throw Error("simulation: a capsule collider has a negative or non-finite radius or end");
  colliders_.assign(spheres.begin(), spheres.end());
  capsules_.assign(capsules.begin(), capsules.end());
}

void SimulatePass::reset(const glm::mat4& head) {
  std::vector<glm::vec4> world(rest_.size());
  for (std::size_t i = 0; i < rest_.size(); ++i) world[i] = point(head, rest_[i]);
  vk::upload<glm::vec4>(ctx_, positions_, world, vk::BufferUse::ComputeWrite);
  vk::upload<glm::vec4>(ctx_, previous_, world, vk::BufferUse::ComputeWrite);
}

gpu::SimFrame SimulatePass::frameConstants(const HeadMotion& motion, bool gridActs) const {
  gpu::SimFrame f{};
  const double h = params_.dt / params_.substeps;
  f.headFrom = motion.from;
  f.headTo = motion.to;
  f.gravity = glm::vec4(glm::vec3(params_.gravity), float(h));
  glm::dvec3 windDir = glm::length(params_.windDirection) > 0.0 ? glm::normalize(params_.windDirection) : glm::dvec3(0.0);
  f.wind = glm::vec4(glm::vec3(windDir * params_.windStrength), float(params_.windGust));
  f.damping = float(params_.damping);
  f.pearlRadius = float(params_.pearlRadius);
  f.stiffness = float(params_.stiffness);
  f.stiffnessFalloff = float(params_.stiffnessFalloff);
  f.localStiffness = float(params_.localStiffness);
  f.maxSpeed = float(params_.maxSpeed);
  f.time = float(motion.time);
  f.gustFrequency = float(params_.windGustFrequency);
  f.teleport = motion.teleport ? 1u : 0u;
  f.guideCount = guideCount_;
  f.substeps = params_.substeps;
  f.iterations = params_.iterations;
  f.colliderCount = static_cast<std::uint32_t>(colliders_.size());
  for (std::size_t c = 0; c < colliders_.size(); ++c) f.colliders[c] = glm::vec4(colliders_[c].center, colliders_[c].radius);
  f.capsuleCount = static_cast<std::uint32_t>(capsules_.size());
  for (std::size_t c = 0; c < capsules_.size(); ++c) {
    f.capsules[2 * c] = glm::vec4(capsules_[c].a, capsules_[c].radius);
    f.capsules[2 * c + 1] = glm::vec4(capsules_[c].b, 0.0f);
  }
  f.scalpMode = scalp_.mode();
  f.boneCount = scalp_.boneCount();
  const HairGridLayout& grid = grid_->layout();
  f.gridOriginCell = glm::vec4(grid.origin, grid.cellSize);
  f.gridDims = glm::uvec4(grid.dims, gridActs ? 1u : 0u);
  // volume (cells a frame per unit of density change over a cell) as a speed per unit of that change, scene
  // units / s; simulate.comp multiplies it by the pressure gradient's size times the cell size.
  f.gridForces = glm::vec4(float(params_.volume * grid.cellSize / params_.dt), float(params_.friction),
                           float(params_.volumeTarget), 0.0f);
  return f;
}

void SimulatePass::record(VkCommandBuffer cmd, const HeadMotion& motion, vk::GpuProfiler* profiler) {
  // The grid holds the hair where it is now; a teleport frame carries it elsewhere first, so it sits out.
  const bool gridActs = params_.gridActs() && !motion.teleport;
  if (character_) {
    if (profiler) profiler->begin(cmd, "character");
    characterPosed_ = character_->record(cmd);
    if (profiler) profiler->end(cmd);
  }
  if (gridActs) {
    if (profiler) profiler->begin(cmd, "simulate grid");
    grid_->record(cmd, glm::inverse(motion.from), params_.dt / params_.substeps, params_.maxSpeed, params_.volumeTarget);
    if (profiler) profiler->end(cmd);
  }
  if (profiler) profiler->begin(cmd, "simulate");
  gpu::SimFrame f = frameConstants(motion, gridActs);
  // The previous frame's dispatch may still read the block: order that read before this write.
  vk::bufferBarrier(ctx_, cmd, frame_.handle(), frameWritten_ ? vk::BufferUse::ComputeRead : vk::BufferUse::None,
                    vk::BufferUse::TransferDst);
  ctx_.fn().vkCmdUpdateBuffer(cmd, frame_.handle(), 0, sizeof(f), &f);
  vk::bufferBarrier(ctx_, cmd, frame_.handle(), vk::BufferUse::TransferDst, vk::BufferUse::ComputeRead);
  frameWritten_ = true;
  scalp_.record(cmd);
  pipeline_->bind(cmd, set_.set());
  pipeline_->dispatch(cmd, guideCount_);
  if (profiler) profiler->end(cmd);
}
}  // namespace hp
