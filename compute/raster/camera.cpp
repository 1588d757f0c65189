#include "compute/raster/camera.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/core/error.h"

namespace hp {
CameraMatrices orbitCamera(const CameraSpec& c, float aspect) {
  if (!(c.distance > 0.0f) || !std::isfinite(c.distance)) throw Error("camera distance must be > 0");
  if (!(c.fovDeg > 0.0f && c.fovDeg < 180.0f)) throw Error("camera fov must be in (0, 180) degrees");
  if (!std::isfinite(c.orbitDeg) || !std::isfinite(c.elevationDeg) || !std::isfinite(glm::length(c.target)))
    throw Error("camera orbit, elevation and target must be finite");
  if (!(aspect > 0.0f) || !std::isfinite(aspect)) throw Error("camera aspect ratio must be > 0");
  const float orbit = glm::radians(c.orbitDeg), elevation = glm::radians(c.elevationDeg);
  glm::vec3 offset(std::sin(orbit) * std::cos(elevation), std::sin(elevation), std::cos(orbit) * std::cos(elevation));
  CameraMatrices m;
  m.position = c.target + offset * c.distance;
  m.fovY = glm::radians(c.fovDeg);
  m.view = glm::lookAtRH(m.position, c.target, glm::vec3(0, 1, 0));
  m.proj = glm::perspectiveRH_ZO(m.fovY, aspect, 0.02f * c.distance, 20.0f * c.distance);
  return m;
}
}  // namespace hp
