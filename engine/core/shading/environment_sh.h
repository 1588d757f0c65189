#pragma once
// Contract: an environment's radiance as the 9 real spherical harmonics of order <= 2 (RGB coefficients in the
// basis and order of shaders/shared/environment.h), projected from an EnvironmentMap with each texel's exact
// solid angle, evaluated at a direction, and convolved with the clamped cosine over pi (what the frame holds:
// evaluated at n it gives irradiance / pi, the cosine-weighted mean radiance around n). Pure host code;
// docs/SHADING.md "Environment".
#include <array>

#include <glm/glm.hpp>

#include "engine/core/shading/environment_map.h"

namespace hp {
using EnvironmentSH = std::array<glm::dvec3, 9>;

EnvironmentSH projectEnvironment(const EnvironmentMap& map);  // validates the map first
// Adds one direction's radiance x solid angle to a projection.
void addToEnvironment(EnvironmentSH& sh, const glm::dvec3& dir, const glm::dvec3& radianceTimesSolidAngle);
EnvironmentSH uniformEnvironmentSH(const glm::dvec3& radiance);
glm::dvec3 evaluateEnvironment(const EnvironmentSH& sh, const glm::dvec3& dir);
EnvironmentSH cosineConvolved(const EnvironmentSH& radiance);
// The radiance seen in another frame's axes: the SH of w -> L(rotation w), rotation taking that frame's axes to
// the SH's (orthonormal). Exact for order <= 2 (a product quadrature that integrates degree-4 polynomials).
EnvironmentSH rotateEnvironment(const EnvironmentSH& radiance, const glm::dmat3& rotation);
}  // namespace hp
