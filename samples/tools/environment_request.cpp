#include "samples/tools/environment_request.h"

#include "engine/core/shading/environment_lights.h"

namespace hp {
namespace {
LightSpec directionalLight(const EnvironmentLight& e) {
  LightSpec l;
  l.direction = glm::vec3(e.direction);
  l.intensity = float(e.intensity());
  l.color = glm::vec3(e.color());
  l.shadows = true;
  return l;
}
}  // namespace

void setEnvironment(RenderRequest& r, std::shared_ptr<const EnvironmentMap> map, std::uint32_t maxLights) {
  r.environmentLights.clear();
  r.look.environment = {};
  r.environment = std::move(map);
  if (!r.environment) return;
  const EnvironmentSplit split = splitEnvironment(*r.environment, {maxLights});
  for (const EnvironmentLight& e : split.lights) r.environmentLights.push_back(directionalLight(e));
  for (std::size_t i = 0; i < split.residual.size(); ++i) r.look.environment[i] = glm::vec3(split.residual[i]);
  r.look.ambient = 0.0f;
}
}  // namespace hp
