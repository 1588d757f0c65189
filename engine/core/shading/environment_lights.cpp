#include "engine/core/shading/environment_lights.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/core/number_text.h"
#include "engine/core/shading/light_limits.h"
#include "engine/core/shading/luminance.h"
#include "engine/core/shading/math_constants.h"

namespace hp {
namespace {
enum class TexelState : std::uint8_t { Dim, Bright, Taken };

// Per texel, 5 bytes: its luminance and whether it is bright or taken (direction and solid angle are
// recomputed where needed: an 8192 x 4096 map stays within 170 MB here).
struct TexelTable {
  const EnvironmentMap& map;
  std::vector<float> luminance;
  std::vector<TexelState> state;

  explicit TexelTable(const EnvironmentMap& m) : map(m), luminance(m.texels.size()), state(m.texels.size()) {
    for (std::uint32_t y = 0; y < m.height; ++y)
      for (std::uint32_t x = 0; x < m.width; ++x) luminance[index(x, y)] = float(luminanceOf(m.texelRadiance(x, y)));
  }
  std::size_t index(std::uint32_t x, std::uint32_t y) const { return std::size_t(y) * map.width + x; }

  void markBright(double factor) {
    double sum = 0.0;
    for (std::uint32_t y = 0; y < map.height; ++y)
      for (std::uint32_t x = 0; x < map.width; ++x) sum += luminance[index(x, y)] * map.texelSolidAngle(y);
    const double threshold = factor * sum / (4.0 * shading::kPi);
    for (std::size_t i = 0; i < luminance.size(); ++i)
      state[i] = luminance[i] > threshold && luminance[i] > 0.0f ? TexelState::Bright : TexelState::Dim;
  }

  // The brightest bright texel nobody took yet, or -1.
  std::ptrdiff_t brightestFree() const {
    std::ptrdiff_t best = -1;
    for (std::size_t i = 0; i < luminance.size(); ++i)
      if (state[i] == TexelState::Bright && (best < 0 || luminance[i] > luminance[std::size_t(best)]))
        best = std::ptrdiff_t(i);
    return best;
  }

  // Every free bright texel within the cluster's cone around `seed` becomes the light's.
  EnvironmentLight gather(const glm::dvec3& seed, double cosCluster) {
    EnvironmentLight light;
    glm::dvec3 weighted(0.0);
    for (std::uint32_t y = 0; y < map.height; ++y)
      for (std::uint32_t x = 0; x < map.width; ++x) {
        const std::size_t i = index(x, y);
        if (state[i] != TexelState::Bright) continue;
        const glm::dvec3 d = map.texelDirection(x, y);
        if (glm::dot(d, seed) < cosCluster) continue;
        state[i] = TexelState::Taken;
        const double omega = map.texelSolidAngle(y);
        light.irradiance += map.texelRadiance(x, y) * omega;
        light.solidAngle += omega;
        weighted += d * (double(luminance[i]) * omega);
      }
    light.direction = glm::length(weighted) > 0.0 ? glm::normalize(weighted) : seed;
    return light;
  }

  // What no light took, projected on the SH.
  EnvironmentSH residual() const {
    EnvironmentSH sh{};
    for (std::uint32_t y = 0; y < map.height; ++y)
      for (std::uint32_t x = 0; x < map.width; ++x)
        if (state[index(x, y)] != TexelState::Taken)
          addToEnvironment(sh, map.texelDirection(x, y), map.texelRadiance(x, y) * map.texelSolidAngle(y));
    return sh;
  }
};

void validate(const EnvironmentSplitSettings& s) {
  if (s.maxLights > kMaxEnvironmentLights) throw Error("environment lights must be in [0, 4]");
  if (!(s.brightFactor > 0.0 && s.brightFactor < 1e6)) throw Error("environment bright factor must be in (0, 1e6)");
  if (!(s.clusterDeg > 0.0 && s.clusterDeg <= 180.0)) throw Error("environment cluster angle must be in (0, 180]");
}
}  // namespace

double EnvironmentLight::intensity() const { return std::max({irradiance.r, irradiance.g, irradiance.b}); }

glm::dvec3 EnvironmentLight::color() const { return intensity() > 0.0 ? irradiance / intensity() : glm::dvec3(1.0); }

EnvironmentSplit splitEnvironment(const EnvironmentMap& map, const EnvironmentSplitSettings& settings) {
  validate(settings);
  map.validate();
  TexelTable table(map);
  table.markBright(settings.brightFactor);
  EnvironmentSplit split;
  const double cosCluster = std::cos(glm::radians(settings.clusterDeg));
  while (split.lights.size() < settings.maxLights) {
    const std::ptrdiff_t seed = table.brightestFree();
    if (seed < 0) break;
    const auto x = std::uint32_t(std::size_t(seed) % map.width), y = std::uint32_t(std::size_t(seed) / map.width);
    split.lights.push_back(table.gather(map.texelDirection(x, y), cosCluster));
  }
  split.residual = table.residual();
  // A bright region becomes a light like any other: within the same bound (light_limits.h).
  for (const EnvironmentLight& light : split.lights)
    if (!(light.intensity() <= double(kMaxLightRadiance)))
      throw Error("environment: a bright region becomes a light of " + numberText(light.intensity()) +
                  ", more than the " + numberText(kMaxLightRadiance) +
                  " a light may be (the radiance images are half floats): lower the environment's intensity");
  return split;
}
}  // namespace hp
