#include "engine/core/shading/environment_sh.h"

#include <cmath>

#include "engine/core/shading/math_constants.h"
#include "shaders/shared/environment.h"

namespace hp {
namespace {
double basis(std::uint32_t i, const glm::dvec3& d) { return gpu::envShBasis(i, glm::vec3(d)); }
}  // namespace

void addToEnvironment(EnvironmentSH& sh, const glm::dvec3& dir, const glm::dvec3& radianceTimesSolidAngle) {
  for (std::uint32_t i = 0; i < gpu::ENV_SH_COEFFICIENTS; ++i) sh[i] += radianceTimesSolidAngle * basis(i, dir);
}

EnvironmentSH projectEnvironment(const EnvironmentMap& map) {
  map.validate();
  EnvironmentSH sh{};
  for (std::uint32_t y = 0; y < map.height; ++y)
    for (std::uint32_t x = 0; x < map.width; ++x)
      addToEnvironment(sh, map.texelDirection(x, y), map.texelRadiance(x, y) * map.texelSolidAngle(y));
  return sh;
}

EnvironmentSH uniformEnvironmentSH(const glm::dvec3& radiance) {
  EnvironmentSH sh{};
  sh[0] = radiance * (2.0 * std::sqrt(shading::kPi));  // int Y_0 d omega = 4 pi Y_0 = 2 sqrt(pi)
  return sh;
}

glm::dvec3 evaluateEnvironment(const EnvironmentSH& sh, const glm::dvec3& dir) {
  glm::dvec3 sum(0.0);
  for (std::uint32_t i = 0; i < gpu::ENV_SH_COEFFICIENTS; ++i) sum += sh[i] * basis(i, dir);
  return sum;
}

EnvironmentSH rotateEnvironment(const EnvironmentSH& radiance, const glm::dmat3& rotation) {
  // Gauss-Legendre in cos(theta) (3 nodes: exact to degree 5) times 6 even steps in phi (exact for
  // trigonometric degree 5): L(R w) Y_i(w) is a polynomial of degree 4 on the sphere.
  const double nodes[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)}, weights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  constexpr int kSteps = 6;
  EnvironmentSH out{};
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < kSteps; ++j) {
      const double z = nodes[k], r = std::sqrt(1.0 - z * z), phi = 2.0 * shading::kPi * j / kSteps;
      const glm::dvec3 w(r * std::cos(phi), r * std::sin(phi), z);
      addToEnvironment(out, w, evaluateEnvironment(radiance, rotation * w) * (weights[k] * 2.0 * shading::kPi / kSteps));
    }
  return out;
}

EnvironmentSH cosineConvolved(const EnvironmentSH& radiance) {
  EnvironmentSH out = radiance;
  for (std::uint32_t i = 0; i < gpu::ENV_SH_COEFFICIENTS; ++i) {
    const double band = i == 0 ? gpu::ENV_COSINE_BAND0 : i < 4 ? gpu::ENV_COSINE_BAND1 : gpu::ENV_COSINE_BAND2;
    out[i] *= band;
  }
  return out;
}
}  // namespace hp
