#pragma once
// Contract: an environment light as an equirectangular image of linear RGB radiance, looked up by world
// direction (bilinear, wrapping around in azimuth), turned about the world's +y axis by rotationDeg and
// scaled by intensity; and the built-in studio environment. Row 0 is straight up (+y), the last row straight
// down; column u in [0, 1) is the azimuth 2 pi u - pi from +z toward +x, so the middle column looks along
// +z (where the default camera stands). Pure host code; docs/SHADING.md "Environment".
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/glm.hpp>

namespace hp {
inline constexpr std::uint64_t kMaxEnvironmentTexels = 8192ull * 4096ull;  // 400 MiB of float RGB
inline constexpr double kMaxEnvironmentRadiance = 1e9;  // texel x intensity: far past the sun's, finite in float

struct EnvironmentMap {
  std::uint32_t width = 0, height = 0;
  std::vector<glm::vec3> texels;  // row-major, width x height
  double rotationDeg = 0.0;       // turns the image about +y (counter-clockwise seen from above)
  double intensity = 1.0;         // scales every texel

  // Radiance arriving from world direction `dir` (unit).
  glm::dvec3 radiance(const glm::dvec3& dir) const;
  // The world direction of image point (u, v) in [0, 1]^2 (u across, v down), and the point of a direction.
  glm::dvec3 direction(double u, double v) const;
  glm::dvec2 imagePoint(const glm::dvec3& dir) const;
  // Texel (x, y): its centre's direction, its solid angle (the band between its rows' polar angles split
  // evenly in azimuth; they sum to 4 pi) and its radiance times the intensity.
  glm::dvec3 texelDirection(std::uint32_t x, std::uint32_t y) const;
  double texelSolidAngle(std::uint32_t y) const;
  glm::dvec3 texelRadiance(std::uint32_t x, std::uint32_t y) const;
  // Throws hp::Error naming the problem: sizes (at least 1 each, at most kMaxEnvironmentTexels in all, texels
  // = width x height), a texel that is not finite or is negative, an intensity outside [0, 1000], a radiance
  // (texel x intensity) above kMaxEnvironmentRadiance or a rotation that is not finite.
  void validate() const;
};

// A map of the given size whose texels hold `radiance` at their centres' directions.
EnvironmentMap sampledEnvironment(std::uint32_t width, std::uint32_t height,
                                  const std::function<glm::dvec3(const glm::dvec3&)>& radiance);
// A photographer's studio, procedural (no file): a dim grey room brighter above than below, a large soft box
// to the front left, and a strip light above and behind the subject for a rim. Built at the given size.
EnvironmentMap studioEnvironment(std::uint32_t width = 256, std::uint32_t height = 128);
// A constant radiance everywhere (1 x 1): the uniform sky.
EnvironmentMap uniformEnvironment(const glm::vec3& radiance);
}  // namespace hp
