#pragma once
// Contract: the framing of the heads' depth shadow map (ShadowMaps::headImage, shaders/head_shadow.glsl)
// for one light, computed on the host around a bounding sphere of every head (world space):
// orthographic along a directional light, perspective from a spot (the cone bounds it when the spot is
// inside the sphere). params is RenderFrame::headShadow: (1, receiver offset toward the light = 3
// texels in scene units, 1 / resolution, one texel in scene units: skin facing away from the light adds
// 2 of them per unit of its slope's tangent, shaders/head_shadow.glsl). A sphere of radius <= 0 (no head)
// gives the off view.
#include <glm/glm.hpp>

#include <cstdint>
#include <span>

#include "engine/core/hair/scene.h"

namespace hp::render {
struct HeadSphere {
  glm::vec3 centre{0.0f};
  float radius = 0.0f;  // <= 0: no head
};
HeadSphere enclose(const HeadSphere& a, const HeadSphere& b);
// A sphere around `points`: centred on their box, out to the farthest (none for no points).
HeadSphere boundingSphere(std::span<const glm::vec3> points);

struct HeadShadowView {
  glm::mat4 viewProj{1.0f};  // world -> map clip (Vulkan depth [0, 1])
  glm::vec4 params{0.0f};    // RenderFrame::headShadow; x = 0: off
  float extentWorld = 0.0f;  // the map's width at the heads' centre, scene units
};
HeadShadowView headShadowView(const LightSpec& light, const HeadSphere& heads, std::uint32_t resolution);
}  // namespace hp::render
