#pragma once
// Contract: the bounds pass (shaders/bounds.comp, shaders/shared/opacity.h). It reduces the light-space
// extent of every render strand vertex (all chunks) on the device and writes gpu::LightSpace into
// its own device buffer: the orthographic light viewProj over the padded x/y box and the 16 slice
// depths z_i = z_near + i d_z. The host never reads it back in the frame loop; later passes bind
// lightSpace() as a storage buffer. Directional light only (the basis comes from its direction).
//
// Recording, in the frame recorder, with barriers between the steps (the pass inserts none):
//   recordReduce(cmd, light)  one dispatch per chunk: atomicMin/Max into LightSpace.minBits/maxBits
//   recordFinalize(cmd)       one dispatch: reads the accumulators, writes the matrices and depths,
//                             and re-arms the accumulators, so every frame starts armed.
// The frame recorder guarantees: before recordReduce, the strand positions' ComputeWrite is visible
// to ComputeRead and the previous frame's reads of lightSpace() are done (-> ComputeWrite); between
// the steps, lightSpace() ComputeWrite -> ComputeWrite; after recordFinalize, ComputeWrite -> the
// readers' use. Construction uploads an armed buffer with a unit box, left in BufferUse::VertexRead.
#include <volk.h>

#include <glm/glm.hpp>

#include <vector>

#include "compute/strand_buffers.h"
#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "shaders/shared/opacity.h"

namespace hp::compute {
// World -> light basis for a directional light (unit `towardLight`): rows x, y and L itself. The up
// hint is +Y unless the light is within ~8 degrees of it, then +X, so the basis is never degenerate.
glm::mat3 lightBasisRows(const glm::vec3& towardLight);

struct BoundsFraming {
  std::uint32_t resolution = 512;  // opacity map texels per side (for the texel padding)
  float marginWorld = 0.0f;        // half the widest strand, scene units
  float marginTexels = 2.0f;       // extra padding so linear filtering stays inside the map
};

class BoundsPass {
 public:
  BoundsPass(const vk::Context& ctx, const StrandBuffers& strands);
  void bind(const StrandBuffers& strands);  // outside the frame loop, after StrandBuffers changed

  void recordReduce(VkCommandBuffer cmd, const glm::vec3& towardLight) const;
  void recordFinalize(VkCommandBuffer cmd, const glm::vec3& towardLight, const BoundsFraming& framing) const;
  const vk::Buffer& lightSpace() const { return lightSpace_; }

 private:
  struct Chunk {
    vk::DescriptorSet set;
    std::uint32_t vertexCount;
  };
  gpu::BoundsPush push(const glm::vec3& towardLight) const;

  const vk::Context* ctx_;
  vk::Buffer lightSpace_;
  vk::DescriptorSet layoutSet_;
  vk::ComputePipeline pipeline_;
  std::vector<Chunk> chunks_;
};

// The armed initial LightSpace (unit box, accumulators at +-max), as uploaded at construction.
gpu::LightSpace initialLightSpace();
}  // namespace hp::compute
