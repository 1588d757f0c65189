#pragma once
// Contract: the bounds pass (shaders/bounds.comp, shaders/shared/opacity.h). It reduces the light-space
// extent of every render strand vertex (all chunks) on the device and writes gpu::LightSpace into
// a device buffer it is given (render::ShadowMaps owns it; several instances' bounds passes reduce into
// the same one, so one framing covers all of them): the orthographic light viewProj over the padded x/y box and the 16 slice
// depths z_i = z_near + i d_z. The host never reads it back in the frame loop; later passes bind
// lightSpace() as a storage buffer. A directional light gets an orthographic framing, a spot light a
// perspective one from its position, capped by its cone (shared/opacity.h has the conventions).
//
// Recording, in the frame recorder, with barriers between the steps (the pass inserts none):
//   recordReduce(cmd, light)  one dispatch per chunk: atomicMin/Max into LightSpace.minBits/maxBits
//                             (every instance sharing the buffer, one after the other: atomics)
//   recordFinalize(cmd)       one dispatch (of any one of them): reads the accumulators, writes the
//                             matrices and depths, and re-arms the accumulators, so every frame starts armed.
// The frame recorder guarantees: before recordReduce, the strand positions' ComputeWrite is visible
// to ComputeRead and the previous frame's reads of lightSpace() are done (-> ComputeWrite); between
// the steps, lightSpace() ComputeWrite -> ComputeWrite; after recordFinalize, ComputeWrite -> the
// readers' use. The buffer starts armed: initialLightSpace() (ShadowMaps uploads it).
#include "hairpipe_volk.h"

#include <glm/glm.hpp>

#include <vector>

#include "compute/strands/strand_buffers.h"
#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline_library.h"
#include "shaders/shared/opacity.h"

namespace hp::compute {
// World -> light basis for a directional light (unit `towardLight`): rows x, y and L itself. The up
// hint is +Y unless the light is within ~8 degrees of it, then +X, so the basis is never degenerate.
glm::mat3 lightBasisRows(const glm::vec3& towardLight);

// The light as the shadow passes see it. Implicit from a direction: a directional light.
struct ShadowLight {
  glm::vec3 towardLight{0.0f, 0.0f, 1.0f};  // unit; spot: minus its axis (from the lit hair toward it)
  bool spot = false;
  glm::vec3 position{0.0f};  // spot: world position
  float coneRadians = 0.5f;  // spot: cone half-angle, (0, 80 deg]
  std::uint32_t slot = 0;    // its shadow slot: which LightSpace of the buffer (shared/opacity.h)
  ShadowLight() = default;
  ShadowLight(const glm::vec3& direction) : towardLight(direction) {}  // NOLINT: a direction is a directional light
  static ShadowLight makeSpot(const glm::vec3& position, const glm::vec3& towardLight, float coneRadians);
};

// Hair closer to a spot than this (scene units, along its axis) is left out of its framing.
inline constexpr float kSpotNearLimit = 1.0e-3f;

struct BoundsFraming {
  std::uint32_t resolution = 512;  // opacity map texels per side (for the texel padding)
  float marginWorld = 0.0f;        // half the widest strand, scene units
  float marginTexels = 2.0f;       // extra padding so linear filtering stays inside the map
};

class BoundsPass {
 public:
  // lightSpace: gpu::LightSpace per shadow slot, storage usage, armed (initialLightSpace); it outlives the pass.
  BoundsPass(const vk::Context& ctx, const StrandBuffers& strands, const vk::Buffer& lightSpace,
             vk::PipelineLibrary* library = nullptr);

  void recordReduce(VkCommandBuffer cmd, const ShadowLight& light) const;
  void recordFinalize(VkCommandBuffer cmd, const ShadowLight& light, const BoundsFraming& framing) const;
  const vk::Buffer& lightSpace() const { return *lightSpace_; }

 private:
  struct Chunk {
    vk::DescriptorSet set;
    std::uint32_t vertexCount;
  };
  gpu::BoundsPush push(const ShadowLight& light) const;
  void bind(const StrandBuffers& strands);

  const vk::Context* ctx_;
  const vk::Buffer* lightSpace_;
  vk::DescriptorSet layoutSet_;
  std::shared_ptr<const vk::ComputePipeline> pipeline_;
  std::vector<Chunk> chunks_;
};

// The armed initial LightSpace (unit box, accumulators at +-max), as uploaded at construction.
gpu::LightSpace initialLightSpace();
}  // namespace hp::compute
