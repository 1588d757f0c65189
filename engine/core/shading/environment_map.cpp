#include "engine/core/shading/environment_map.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/core/shading/math_constants.h"

namespace hp {
namespace {
// (u, v) of a direction of the unturned image.
glm::dvec2 unturnedImagePoint(const glm::dvec3& d) {
  const double azimuth = std::atan2(d.x, d.z);  // 0 along +z, pi / 2 along +x
  const double polar = std::acos(std::clamp(d.y, -1.0, 1.0));
  return {azimuth / (2.0 * shading::kPi) + 0.5, polar / shading::kPi};
}

glm::dvec3 turned(const glm::dvec3& d, double degrees) {
  const double a = glm::radians(degrees), c = std::cos(a), s = std::sin(a);
  return {c * d.x + s * d.z, d.y, -s * d.x + c * d.z};
}

double smoothEdge(double edge0, double edge1, double x) {
  const double t = std::clamp((x - edge0) / (edge1 - edge0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}

// A round light of the studio: radiance inside `radiusDeg` of `axis`, fading out over its last `softDeg`.
glm::dvec3 softDisc(const glm::dvec3& dir, const glm::dvec3& axis, double radiusDeg, double softDeg,
                    const glm::dvec3& radiance) {
  const double angle = glm::degrees(std::acos(std::clamp(glm::dot(dir, glm::normalize(axis)), -1.0, 1.0)));
  return radiance * (1.0 - smoothEdge(radiusDeg - softDeg, radiusDeg, angle));
}

glm::dvec3 studioRadiance(const glm::dvec3& d) {
  // The room: 0.09 overhead, 0.05 at the horizon, 0.025 from the (warmer) floor.
  const glm::dvec3 room = d.y >= 0.0 ? glm::mix(glm::dvec3(0.05), glm::dvec3(0.09), d.y)
                                     : glm::mix(glm::dvec3(0.05), glm::dvec3(0.03, 0.025, 0.02), -d.y);
  const glm::dvec3 softBox = softDisc(d, {-0.7, 0.35, 0.65}, 28.0, 10.0, {1.1, 1.16, 1.24});
  const glm::dvec3 rim = softDisc(d, {0.15, 0.7, -0.7}, 20.0, 8.0, {3.0, 2.8, 2.5});
  return room + softBox + rim;
}
}  // namespace

glm::dvec3 EnvironmentMap::direction(double u, double v) const {
  const double azimuth = (u - 0.5) * 2.0 * shading::kPi, polar = v * shading::kPi;
  const glm::dvec3 local(std::sin(polar) * std::sin(azimuth), std::cos(polar), std::sin(polar) * std::cos(azimuth));
  return turned(local, rotationDeg);
}

glm::dvec2 EnvironmentMap::imagePoint(const glm::dvec3& dir) const {
  return unturnedImagePoint(turned(dir, -rotationDeg));
}

glm::dvec3 EnvironmentMap::texelDirection(std::uint32_t x, std::uint32_t y) const {
  return direction((x + 0.5) / width, (y + 0.5) / height);
}

double EnvironmentMap::texelSolidAngle(std::uint32_t y) const {
  const double top = shading::kPi * y / height, bottom = shading::kPi * (y + 1) / height;
  return (std::cos(top) - std::cos(bottom)) * 2.0 * shading::kPi / width;
}

glm::dvec3 EnvironmentMap::texelRadiance(std::uint32_t x, std::uint32_t y) const {
  return intensity * glm::dvec3(texels[std::size_t(y) * width + x]);
}

glm::dvec3 EnvironmentMap::radiance(const glm::dvec3& dir) const {
  const glm::dvec2 p = imagePoint(dir);
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return glm::dvec3(0.0);  // no direction: no light
  // Texel centres at (i + 0.5) / size; azimuth wraps, the poles clamp.
  const double x = p.x * width - 0.5, y = std::clamp(p.y * height - 0.5, 0.0, double(height - 1));
  const double fx = std::floor(x), fy = std::floor(y);
  const auto column = [&](double c) { return std::uint32_t((std::int64_t(c) % width + width) % width); };
  const std::uint32_t x0 = column(fx), x1 = column(fx + 1.0);
  const std::uint32_t y0 = std::uint32_t(fy), y1 = std::min(y0 + 1, height - 1);
  const double tx = x - fx, ty = y - fy;
  const auto at = [&](std::uint32_t cx, std::uint32_t cy) { return glm::dvec3(texels[std::size_t(cy) * width + cx]); };
  const glm::dvec3 top = glm::mix(at(x0, y0), at(x1, y0), tx), bottom = glm::mix(at(x0, y1), at(x1, y1), tx);
  return intensity * glm::mix(top, bottom, ty);
}

void EnvironmentMap::validate() const {
  if (width < 1 || height < 1 || std::uint64_t(width) * height > kMaxEnvironmentTexels)
    throw Error("environment image size " + std::to_string(width) + "x" + std::to_string(height) +
                " is outside 1x1..8192x4096 texels");
  if (texels.size() != std::size_t(width) * height) throw Error("environment image holds the wrong number of texels");
  if (!(intensity >= 0.0 && intensity <= 1000.0)) throw Error("environment intensity must be in [0, 1000]");
  if (!std::isfinite(rotationDeg)) throw Error("environment rotation must be finite");
  for (const glm::vec3& t : texels)
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(t[c]) || t[c] < 0.0f) throw Error("environment image holds a negative or non-finite radiance");
      if (double(t[c]) * intensity > kMaxEnvironmentRadiance)
        throw Error("environment radiance above 1e9 (texel x intensity)");
    }
}

EnvironmentMap sampledEnvironment(std::uint32_t width, std::uint32_t height,
                                  const std::function<glm::dvec3(const glm::dvec3&)>& radiance) {
  EnvironmentMap map;
  map.width = width;
  map.height = height;
  map.texels.resize(std::size_t(width) * height);
  for (std::uint32_t y = 0; y < height; ++y)
    for (std::uint32_t x = 0; x < width; ++x)
      map.texels[std::size_t(y) * width + x] = glm::vec3(radiance(map.texelDirection(x, y)));
  return map;
}

EnvironmentMap studioEnvironment(std::uint32_t width, std::uint32_t height) {
  return sampledEnvironment(width, height, studioRadiance);
}

EnvironmentMap uniformEnvironment(const glm::vec3& radiance) { return {1, 1, {radiance}, 0.0, 1.0}; }
}  // namespace hp
