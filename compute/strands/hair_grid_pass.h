#pragma once
// Contract: the hair density / velocity grid of one simulated instance on the device (docs/THEORY.md §2.7,
// layout and passes in shaders/shared/hair_grid.h). Owns the accumulation buffer, the resolved cells that
// simulate.comp reads, the run's peak density and the two pipelines. The grid's place and cell size are fixed
// at construction (hairGridLayout of the rest pose), so the buffers behind the simulation's descriptor never
// change. record() clears, splats the particles as they are now and resolves: before it, the caller has
// finished writing positions/previous (ComputeWrite); after it, cells() is ready for compute reads and the
// particles for compute writes (it ends on a global compute barrier).
#include <glm/glm.hpp>

#include <span>

#include "engine/core/hair/hair_grid_layout.h"
#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline_library.h"
#include "shaders/shared/hair_grid.h"

namespace hp {
class HairGridPass {
 public:
  // Throws hp::Error on a bad resolution or a grid past the device's maxStorageBufferRange.
  HairGridPass(const vk::Context& ctx, std::span<const glm::vec4> rest, std::uint32_t particlesPerGuide,
               std::uint32_t resolution, float pearlRadius, const vk::Buffer& positions, const vk::Buffer& previous,
               vk::PipelineLibrary* library);

  // `worldToHead`: where the particles are now, into head space; `substep`: the time between positions and
  // previous; `target`: the volume target in rest-mean units.
  void record(VkCommandBuffer cmd, const glm::mat4& worldToHead, double substep, double maxSpeed, double target);

  const HairGridLayout& layout() const { return layout_; }
  double restMeanDensity() const { return restMean_; }  // weight per cell
  float fixedPoint() const { return fixedPoint_; }
  const vk::Buffer& accumulation() const { return accum_; }
  const vk::Buffer& cells() const { return cells_; }
  // One uint: the float bits of the largest density in the grid last recorded.
  const vk::Buffer& peak() const { return peak_; }

 private:
  const vk::Context& ctx_;
  HairGridLayout layout_;
  std::uint32_t particles_;
  std::uint32_t particlesPerGuide_;
  double restMean_;
  float fixedPoint_;
  vk::Buffer accum_;
  vk::Buffer cells_;
  vk::Buffer peak_;
  vk::DescriptorSet set_;
  std::shared_ptr<const vk::ComputePipeline> splat_;
  std::shared_ptr<const vk::ComputePipeline> resolve_;
};
}  // namespace hp
