#pragma once
// Contract: CPU emulation of what the shader does with the LUTs, so LUT accuracy is measured on the
// CPU. sampleBilinear() is the GPU's bilinear filter with clamp-to-edge addressing: texel centres at
// (i + 0.5)/n, weights from u*n - 0.5, optionally quantised to subTexelBits fractional bits like
// hardware filtering (0 = exact; NVIDIA/AMD use 8). Arithmetic is single precision, like the GPU.
// evaluateLut() runs the marschnerLutPaper / marschnerLutFloat / marschnerLutPhysical shader logic of shaders/marschner.glsl
// (same shared coordinate functions from shaders/shared/marschner.h) and returns S.
#include <glm/glm.hpp>

#include "engine/core/shading/lut.h"

namespace hp {
struct LutSamplerOptions {
  int subTexelBits = 0;
};

glm::vec4 sampleBilinear(const LutTexture& texture, float u, float v, const LutSamplerOptions& options = {});

// S from the LUT for non-zero L, V, T. Throws hp::Error for LutMode::Direct (nothing to sample). tilt: the
// fibre's cuticle tilt offset from the material's alpha_R (radians), roughness: the scale of its beta_R (read
// from the M texture's layer of it); the physical mode takes both as the shader does (marschnerPhysicalM),
// the paper and float modes ignore them.
glm::dvec3 evaluateLut(const MarschnerLut& lut, glm::dvec3 L, glm::dvec3 V, glm::dvec3 T,
                       const LutSamplerOptions& options = {}, float tilt = 0.0f, float roughness = 1.0f);
}  // namespace hp
