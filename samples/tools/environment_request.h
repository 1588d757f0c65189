#pragma once
// Contract: lights a render request with an environment (engine/core/shading/environment_lights.h): the map
// kept for the frame export, its bright regions (up to maxLights) as shadowed directional lights after the
// scene's, the rest as the look's SH, and the uniform ambient set to 0 (the environment is the sky). A null
// map clears all three and leaves the ambient. hp::Error from the split's checks.
#include <cstdint>
#include <memory>

#include "samples/tools/render_job.h"

namespace hp {
void setEnvironment(RenderRequest& request, std::shared_ptr<const EnvironmentMap> map, std::uint32_t maxLights);
}  // namespace hp
