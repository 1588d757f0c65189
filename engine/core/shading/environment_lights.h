#pragma once
// Contract: splits an environment into what real-time shading can draw well: its bright regions (a soft box,
// a window, the sun) become up to `maxLights` directional lights, drawn with the full fibre model and
// shadowed through the opacity maps, and everything else (the room, the sky's gradient) the order-2 SH the
// ambient term takes. A texel is bright when its luminance exceeds `brightFactor` x the environment's mean;
// the brightest bright texel starts a light, which takes every bright texel within `clusterDeg` of it, and
// so on. A light's direction is its texels' luminance-weighted mean direction, its irradiance the sum of
// their radiance x solid angle (what a surface facing it receives, the region treated as a point). Bright
// texels no light took stay in the SH. Every texel's light lands in exactly one of the two (tested). A
// light brighter than kMaxLightRadiance (light_limits.h) is refused (hp::Error naming the environment). Pure
// host code; docs/SHADING.md "Environment".
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/shading/environment_map.h"
#include "engine/core/shading/environment_sh.h"
#include "shaders/shared/opacity.h"

namespace hp {
// At most as many as there are shadow slots.
inline constexpr std::uint32_t kMaxEnvironmentLights = gpu::OPACITY_MAX_LIGHTS;

struct EnvironmentLight {
  glm::dvec3 direction{0.0, 1.0, 0.0};  // unit, toward the light
  glm::dvec3 irradiance{0.0};           // linear RGB, on a surface facing it
  double solidAngle = 0.0;              // of the texels it took (steradians)
  // The irradiance as a light's intensity (its largest channel) times its colour (over that channel).
  double intensity() const;
  glm::dvec3 color() const;
};

struct EnvironmentSplit {
  std::vector<EnvironmentLight> lights;  // brightest first
  EnvironmentSH residual;                // the radiance the lights did not take
};

struct EnvironmentSplitSettings {
  std::uint32_t maxLights = 2;  // [0, kMaxEnvironmentLights]
  double brightFactor = 4.0;    // > 0
  double clusterDeg = 45.0;     // (0, 180]
};

EnvironmentSplit splitEnvironment(const EnvironmentMap& map, const EnvironmentSplitSettings& settings = {});
}  // namespace hp
