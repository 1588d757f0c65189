#pragma once
// Contract: the lights of one frame as the shadow and shading passes take them. assignShadowSlots gives each
// light that casts shadows (LightSpec::shadows) a shadow slot (shared/opacity.h), in the order given, while
// the Renderer's slots last; the others shade unshadowed. Per slot, the Renderer's recordShadows fills the
// heads' depth map framing. Pure host code; hp::Error for an invalid light or more than RENDER_MAX_LIGHTS.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "compute/shadows/head_shadow_view.h"
#include "engine/core/hair/scene.h"
#include "shaders/shared/opacity.h"

namespace hp::render {
struct FrameLights {
  std::vector<LightSpec> lights;  // [0, RENDER_MAX_LIGHTS]
  std::vector<int> slots;         // per light: its shadow slot, -1: unshadowed
  std::array<HeadShadowView, gpu::OPACITY_MAX_LIGHTS> headViews{};  // per slot (off until recordShadows frames it)

  std::uint32_t shadowed() const;          // slots in use
  int lightOfSlot(std::uint32_t slot) const;  // the light index in that slot, -1: none
};

FrameLights assignShadowSlots(std::span<const LightSpec> lights, std::uint32_t slotCount);

// The light the shadow passes frame for `light`: itself for a directional light or a spot; for a point light,
// a spot at its position aimed at the heads' centre with the widest cone (80 degrees half-angle: the bounds
// pass fits the hair inside it; hair outside the cone is not in the map and stays lit). A point light at
// the centre aims down.
LightSpec shadowFrustum(const LightSpec& light, const HeadSphere& heads);
}  // namespace hp::render
