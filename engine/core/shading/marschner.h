#pragma once
// Contract: the exact Marschner scattering function S of docs/THEORY.md §3, double precision, per RGB.
//   S = sum_p M_p(theta_h) N_p(theta_d, phi) / cos^2(theta_d),  p in {R, TT, TRT}.
// Inputs: L (toward light), V (toward eye), T (tangent); need not be normalised, must be non-zero.
// Degenerate cases are finite, never NaN:
//  - L or V parallel to T (no azimuth): cos phi = 0 (phi = pi/2), the same rule as the shader;
//  - |theta_d| -> pi/2 (L = -V = +-T): cos theta_d is floored at kMinCosThetaD.
// S is symmetric under swapping L and V (theta_d -> -theta_d and every factor is even in theta_d).
#include <glm/glm.hpp>

#include "engine/core/shading/material.h"

namespace hp {
inline constexpr double kMinCosThetaD = 1e-6;

struct ShadingAngles {
  double sinThetaI = 0, sinThetaR = 0, cosPhi = 1;
};
ShadingAngles shadingAngles(glm::dvec3 L, glm::dvec3 V, glm::dvec3 T);

// The separated lobes at one configuration: S = (M_R N_R + M_TT N_TT + M_TRT N_TRT) / cos^2 theta_d.
struct MarschnerLobes {
  double mR = 0, mTT = 0, mTRT = 0;
  double nR = 0;
  glm::dvec3 nTT{0.0}, nTRT{0.0};
  double cosThetaD = 1;
  glm::dvec3 total() const;
};
MarschnerLobes marschnerLobes(double sinThetaI, double sinThetaR, double cosPhi, const HairMaterial& m);

glm::dvec3 marschnerS(double sinThetaI, double sinThetaR, double cosPhi, const HairMaterial& m);
glm::dvec3 marschnerS(glm::dvec3 L, glm::dvec3 V, glm::dvec3 T, const HairMaterial& m);
}  // namespace hp
