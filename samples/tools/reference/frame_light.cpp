#include "samples/tools/reference/frame_light.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hp::reference {
namespace {
constexpr double kSpotInnerFraction = 0.8;  // compute/raster/frame_block.cpp

double smoothstep(double e0, double e1, double x) {
  const double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
}  // namespace

LightArrival lightArrival(const LightSpec& light, const glm::dvec3& p) {
  LightArrival a;
  const glm::dvec3 e = glm::dvec3(light.color) * double(light.intensity);
  const glm::dvec3 direction = glm::normalize(glm::dvec3(light.direction));
  if (light.type == LightSpec::Type::Directional) {
    a.L = direction;
    a.irradiance = e;
    a.distance = std::numeric_limits<double>::infinity();
    return a;
  }
  const glm::dvec3 toLight = glm::dvec3(light.position) - p;
  a.distance = glm::length(toLight);
  a.L = toLight / std::max(a.distance, 1e-6);
  double scale = 1.0;  // a point light: no cone
  if (light.type == LightSpec::Type::Spot) {
    const double cone = glm::radians(double(light.coneDeg));
    scale = smoothstep(std::cos(cone), std::cos(kSpotInnerFraction * cone), glm::dot(a.L, direction));
  }
  if (light.range > 0.0f) {
    const double r = light.range / std::max(a.distance, 0.1 * light.range);
    scale *= r * r;
  }
  a.irradiance = e * scale;
  return a;
}
}  // namespace hp::reference
