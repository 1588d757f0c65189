#include "engine/core/shading/environment_lights.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/core/shading/math_constants.h"

namespace hp {
namespace {
struct Texel {
  glm::dvec3 direction, radiance;
  double solidAngle, luminance;
  bool bright, taken;
};

double luminanceOf(const glm::dvec3& rgb) { return 0.2126 * rgb.r + 0.7152 * rgb.g + 0.0722 * rgb.b; }

std::vector<Texel> texelsOf(const EnvironmentMap& map) {
  std::vector<Texel> texels;
  texels.reserve(map.texels.size());
  for (std::uint32_t y = 0; y < map.height; ++y)
    for (std::uint32_t x = 0; x < map.width; ++x) {
      const glm::dvec3 radiance = map.texelRadiance(x, y);
      texels.push_back({map.texelDirection(x, y), radiance, map.texelSolidAngle(y), luminanceOf(radiance), false, false});
    }
  return texels;
}

void markBright(std::vector<Texel>& texels, double factor) {
  double sum = 0.0;
  for (const Texel& t : texels) sum += t.luminance * t.solidAngle;
  const double threshold = factor * sum / (4.0 * shading::kPi);
  for (Texel& t : texels) t.bright = t.luminance > threshold && t.luminance > 0.0;
}

// The brightest bright texel nobody took yet, or -1.
std::ptrdiff_t brightestFree(const std::vector<Texel>& texels) {
  std::ptrdiff_t best = -1;
  for (std::size_t i = 0; i < texels.size(); ++i)
    if (texels[i].bright && !texels[i].taken && (best < 0 || texels[i].luminance > texels[best].luminance))
      best = std::ptrdiff_t(i);
  return best;
}

EnvironmentLight gather(std::vector<Texel>& texels, const glm::dvec3& seed, double cosCluster) {
  EnvironmentLight light;
  glm::dvec3 weighted(0.0);
  for (Texel& t : texels) {
    if (!t.bright || t.taken || glm::dot(t.direction, seed) < cosCluster) continue;
    t.taken = true;
    light.irradiance += t.radiance * t.solidAngle;
    light.solidAngle += t.solidAngle;
    weighted += t.direction * (t.luminance * t.solidAngle);
  }
  light.direction = glm::length(weighted) > 0.0 ? glm::normalize(weighted) : seed;
  return light;
}

void validate(const EnvironmentSplitSettings& s) {
  if (s.maxLights > 4) throw Error("environment lights must be in [0, 4]");
  if (!(s.brightFactor > 0.0 && s.brightFactor < 1e6)) throw Error("environment bright factor must be in (0, 1e6)");
  if (!(s.clusterDeg > 0.0 && s.clusterDeg <= 180.0)) throw Error("environment cluster angle must be in (0, 180]");
}
}  // namespace

double EnvironmentLight::intensity() const { return std::max({irradiance.r, irradiance.g, irradiance.b}); }

glm::dvec3 EnvironmentLight::color() const { return intensity() > 0.0 ? irradiance / intensity() : glm::dvec3(1.0); }

EnvironmentSplit splitEnvironment(const EnvironmentMap& map, const EnvironmentSplitSettings& settings) {
  validate(settings);
  map.validate();
  std::vector<Texel> texels = texelsOf(map);
  markBright(texels, settings.brightFactor);
  EnvironmentSplit split;
  const double cosCluster = std::cos(glm::radians(settings.clusterDeg));
  while (split.lights.size() < settings.maxLights) {
    const std::ptrdiff_t seed = brightestFree(texels);
    if (seed < 0) break;
    split.lights.push_back(gather(texels, texels[std::size_t(seed)].direction, cosCluster));
  }
  split.residual = {};
  for (const Texel& t : texels)
    if (!t.taken) addToEnvironment(split.residual, t.direction, t.radiance * t.solidAngle);
  return split;
}
}  // namespace hp
