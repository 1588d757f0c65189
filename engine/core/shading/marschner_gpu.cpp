#include "engine/core/shading/marschner_gpu.h"

#include "engine/core/error.h"
#include "engine/core/shading/fibre_model.h"
#include "engine/core/shading/furnace.h"
#include "engine/core/shading/math_constants.h"
#include "engine/core/shading/multiple_scattering.h"
#include "shaders/shared/brdf_eval.h"

namespace hp {
static_assert(sizeof(gpu::BrdfEvalInput) == 48);
static_assert(sizeof(gpu::BrdfEvalPush) == 16);

std::uint32_t gpuModeOf(LutMode mode) {
  switch (mode) {
    case LutMode::Paper: return gpu::MARSCHNER_MODE_LUT_PAPER;
    case LutMode::Float: return gpu::MARSCHNER_MODE_LUT_FLOAT;
    case LutMode::Physical: return gpu::MARSCHNER_MODE_LUT_PHYSICAL;
    case LutMode::Direct: break;
  }
  return gpu::MARSCHNER_MODE_DIRECT;
}

gpu::MarschnerParams marschnerGpuParams(const MarschnerLut& lut) {
  const HairMaterial& m = lut.material;
  gpu::MarschnerParams p{};
  p.absorption = glm::vec4(glm::vec3(m.absorption), float(m.eta));
  p.longitudinal = glm::vec4(float(m.alphaR), float(m.betaR), float(m.kG), float(m.wc));
  p.caustic = glm::vec4(float(m.dEta), float(m.dhM), float(m.tiltVariation), float(m.roughnessVariation));
  glm::vec4* scales[3] = {&p.mScale, &p.n0Scale, &p.n1Scale};
  for (int t = 0; t < 3; ++t) {
    *scales[t] = glm::vec4(1.0f);
    if (t < int(lut.textures.size())) {
      const auto& s = lut.textures[t].scale;
      *scales[t] = glm::vec4(s[0], s[1], s[2], s[3]);
    }
  }
  p.control = glm::uvec4(gpuModeOf(lut.mode), 0u, 0u, 0u);
  p.skyAlbedo = glm::vec4(glm::vec3(skyAlbedo(fibreModelOf(lut.mode), m)), 0.0f);
  p.skyAlbedoFront = glm::vec4(glm::vec3(skyAlbedoOver(fibreModelOf(lut.mode), m, 0.0, 0.5 * shading::kPi)), 0.0f);
  if (lut.mode != LutMode::Physical) return p;
  const MultipleScatteringTables& t = lut.multipleScattering;
  if (t.forwardAlbedo.size() != gpu::MARSCHNER_SPREAD_ENTRIES)
    throw Error("marschnerGpuParams: a physical LUT without its multiple-scattering tables");
  p.skyVisibility = glm::vec4(glm::vec3(skyVisibility(t)), 0.0f);
  p.forwardMean = glm::vec4(glm::vec3(meanForwardAlbedo(t)), 0.0f);
  for (std::uint32_t k = 0; k < gpu::MARSCHNER_SPREAD_ENTRIES; ++k) {
    p.forwardAlbedo[k] = glm::vec4(glm::vec3(t.forwardAlbedo[k]), 0.0f);
    p.meanRTT[k] = glm::vec4(float(t.meanR[k]), glm::vec3(t.meanTT[k]));
    p.meanTRT[k] = glm::vec4(glm::vec3(t.meanTRT[k]), 0.0f);
    p.backScatter[k] = glm::vec4(glm::vec3(t.backScatter[k]), 0.0f);
  }
  return p;
}
}  // namespace hp
