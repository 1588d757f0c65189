#pragma once
// Contract: evaluates the Marschner S ON THE DEVICE for a list of (L, V, T) with shaders/brdf_eval.comp,
// in the mode and material of a MarschnerTextures (its UBO and LUTs are bound as they are). Vectors need
// not be normalised but must be non-zero and finite (the caller checks; the shader does not). Blocking,
// outside the frame loop: inputs are uploaded, the kernel runs, outputs are read back, one chunk at a
// time. A chunk holds at most maxRowsPerChunk rows and never more than the device's
// maxStorageBufferRange allows for the input or the output binding, so any row count works with
// bounded device memory. Results come back in input order.
#include <cstdint>

#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"

namespace hp::vk {
class Context;
}

namespace hp::render {
class MarschnerTextures;

struct BrdfQuery {
  glm::vec3 L;  // toward the light
  glm::vec3 V;  // toward the eye
  glm::vec3 T;  // fibre tangent, root to tip
  float tilt = 0.0f;  // the fibre's cuticle tilt offset from the material's alpha_R (radians; physical, direct)
  float roughness = 1.0f;  // the scale of its beta_R (physical, direct)
};

class BrdfEvaluator {
 public:
  static constexpr std::uint32_t kDefaultRowsPerChunk = 1u << 20;

  explicit BrdfEvaluator(const vk::Context& ctx, std::uint32_t maxRowsPerChunk = kDefaultRowsPerChunk);
  // S (rgb) per query, same order. Rebinds `textures` on every call, so it may have been rebuilt since.
  std::vector<glm::vec3> evaluate(const MarschnerTextures& textures, std::span<const BrdfQuery> queries);
  std::uint32_t rowsPerChunk() const { return rowsPerChunk_; }

 private:
  const vk::Context& ctx_;
  std::uint32_t rowsPerChunk_;
  vk::DescriptorSet set_;
  vk::ComputePipeline pipeline_;
};

// One-shot convenience: builds a BrdfEvaluator and evaluates.
std::vector<glm::vec3> evaluateBrdfOnDevice(const vk::Context& ctx, const MarschnerTextures& textures,
                                            std::span<const BrdfQuery> queries);
}  // namespace hp::render
