#include "compute/shadows/frame_lights.h"

#include <string>

#include "engine/core/error.h"
#include "shaders/shared/render.h"

namespace hp::render {
std::uint32_t FrameLights::shadowed() const {
  std::uint32_t n = 0;
  for (int s : slots) n += s >= 0 ? 1u : 0u;
  return n;
}

int FrameLights::lightOfSlot(std::uint32_t slot) const {
  for (std::size_t i = 0; i < slots.size(); ++i)
    if (slots[i] == int(slot)) return int(i);
  return -1;
}

FrameLights assignShadowSlots(std::span<const LightSpec> lights, std::uint32_t slotCount) {
  if (lights.size() > gpu::RENDER_MAX_LIGHTS)
    throw Error("a frame takes at most " + std::to_string(gpu::RENDER_MAX_LIGHTS) + " lights, got " +
                std::to_string(lights.size()));
  FrameLights f;
  for (const LightSpec& l : lights) {
    l.validate();
    const std::uint32_t used = f.shadowed();
    f.lights.push_back(l);
    f.slots.push_back(l.shadows && used < slotCount ? int(used) : -1);
  }
  return f;
}

LightSpec shadowFrustum(const LightSpec& light, const HeadSphere& heads) {
  if (light.type != LightSpec::Type::Point) return light;
  LightSpec spot = light;
  spot.type = LightSpec::Type::Spot;
  spot.coneDeg = 80.0f;
  const glm::vec3 toCentre = heads.centre - light.position;
  const float dist = glm::length(toCentre);
  spot.direction = dist > 1e-6f ? -toCentre / dist : glm::vec3(0.0f, 1.0f, 0.0f);
  return spot;
}
}  // namespace hp::render
