#pragma once
// Contract: one of the exported frame's lights at a point for the path tracer, the same definition as the
// shaders' (shaders/shared/light.h): a directional light gives irradiance colour x intensity on a surface
// facing it; a spot gives that inside 80% of its cone, a smoothstep to 0 at the cone's edge; a point light
// gives it in every direction from its position; spot and point lights times (range / max(d, range / 10))^2
// when range > 0. `distance` bounds the shadow ray (infinite for the sun). The path tracer sums the
// lights, each with its own shadow ray.
#include <glm/glm.hpp>

#include "engine/core/hair/scene.h"

namespace hp::reference {
struct LightArrival {
  glm::dvec3 L{0.0};           // unit, toward the light
  glm::dvec3 irradiance{0.0};  // on a surface facing L, before shadowing
  double distance = 0.0;
};

LightArrival lightArrival(const LightSpec& light, const glm::dvec3& p);
}  // namespace hp::reference
