// Shared by GLSL and C++: the light at a point (FrameLight in shared/render.h), written in the common subset
// so the shading passes (shaders/light.glsl) and the host (the skin's light, compute/raster/frame_block.cpp)
// take a spot's cone and a light's falloff from one formula.
// Directional: L = direction everywhere, full radiance. Spot and point: L = normalize(position - p), and the
// radiance is scaled by
//   cone (spot): smoothstep(cos(cone), cos(inner), dot(L, -axis)): 1 inside the inner angle (80% of the
//                half-angle), fading to 0 at the cone's edge, 0 outside (no direct light);
//   distance:    (range / max(distance, range / 10))^2 when range > 0 (inverse square, 1 at `range`,
//                clamped near the light), 1 when range = 0.
#ifndef HP_SHARED_LIGHT_H
#define HP_SHARED_LIGHT_H
#include "render.h"

#ifdef __cplusplus
#define HP_LIGHT_FN inline
namespace hp::gpu {
using vec3 = glm::vec3;
using glm::dot;
using glm::length;
using glm::max;
using glm::smoothstep;
}  // namespace hp::gpu
#else
#define HP_LIGHT_FN
#endif

HP_BEGIN
struct LightSample {
  vec3 L;       // unit, from p toward the light
  float scale;  // fraction of the light's radiance reaching p (before shadowing)
};

HP_LIGHT_FN LightSample sampleLight(FrameLight light, vec3 p) {
  LightSample s;
  s.L = vec3(light.direction);
  s.scale = 1.0f;
  if (light.position.w == RENDER_LIGHT_DIRECTIONAL) return s;
  vec3 toLight = vec3(light.position) - p;
  float dist = length(toLight);
  s.L = toLight / max(dist, 1e-6f);
  if (light.position.w == RENDER_LIGHT_SPOT)  // direction = -axis: both toward the light
    s.scale = smoothstep(light.spot.x, light.spot.y, dot(s.L, vec3(light.direction)));
  if (light.spot.z > 0.0f) {
    float r = light.spot.z / max(dist, 0.1f * light.spot.z);
    s.scale *= r * r;
  }
  return s;
}
HP_END
#endif
