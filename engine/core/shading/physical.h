#pragma once
// Contract: the exact (double precision) S of the energy-conserving `physical` fibre model
// (docs/THEORY.md §4; conventions in engine/core/shading/physical_terms.h):
//   S = [M_R N_R + M_TT N_TT + M_TRT (N_TRT + N_res)] / cos theta_i,
// so that the shaders' radiance S cos(theta_i) E is the fibre's far-field scattering and
// int S cos(theta_i) d omega_i <= 1 (= 1 without absorption). The residual (p >= 3) takes the TRT
// lobe's longitudinal term (variance AND tilt), which keeps the device form at three textures.
// cos theta_i is floored at kPhysicalMinCosThetaI (S cos theta_i stays finite everywhere).
// Degenerate azimuth (L or V parallel to T): cos phi = 0, as for the Marschner model.
#include <glm/glm.hpp>

#include "engine/core/shading/material.h"
#include "engine/core/shading/physical_terms.h"

namespace hp {
inline constexpr double kPhysicalMinCosThetaI = 1e-4;

struct PhysicalLobes {
  double mR = 0, mTT = 0, mTRT = 0;
  shading::PhysicalN n;
  double cosThetaI = 1;
  glm::dvec3 total() const;  // S
};
PhysicalLobes physicalLobes(double sinThetaI, double sinThetaR, double cosPhi, const HairMaterial& m);

glm::dvec3 physicalS(double sinThetaI, double sinThetaR, double cosPhi, const HairMaterial& m);
glm::dvec3 physicalS(glm::dvec3 L, glm::dvec3 V, glm::dvec3 T, const HairMaterial& m);
}  // namespace hp
