#pragma once
// Contract: importance sampling of incoming directions at a fibre for the path tracer. A one-sample
// mixture whose density pdf() evaluates exactly, so S cos(theta_i) / pdf is unbiased for any fibre
// model: 20% uniform over the sphere (covers every tail), 80% the fibre's lobe shape, i.e.
//   longitudinal: theta_h = (theta_i + theta_r) / 2 ~ Gaussian about the lobe's shift with its width
//     (R: alpha, beta; TT: -alpha/2, beta/2; TRT: -3 alpha/2, 2 beta; picked 40/30/30), the material's
//     own alpha_R and beta_R, so a sample lands where M_p is large (theta_i outside [-90, 90] deg: a zero
//     direction, the sample carries nothing, which keeps the density exact);
//   azimuthal: phi (between the projections of L and V) uniform (50%) or a wrapped Gaussian at
//     phi = pi (50%, width 0.4 rad) where the transmission lobe TT sits.
// theta angles are the Marschner ones: sin(theta) = dot(direction, T).
#include <glm/glm.hpp>

#include "engine/core/shading/material.h"
#include "samples/tools/reference/sampling.h"

namespace hp::reference {
class FibreSampler {
 public:
  FibreSampler(const glm::dvec3& tangent, const glm::dvec3& toEye, const HairMaterial& material);
  glm::dvec3 sample(Sampler& rng) const;      // unit direction toward the light, or 0 (a lost sample)
  double pdf(const glm::dvec3& dir) const;    // solid-angle density of sample()

 private:
  double longitudinalPdf(double thetaI) const;  // density of theta_i from the lobe mixture
  double azimuthPdf(double phi) const;          // density of phi in [-pi, pi)
  FibreFrame frame_;
  double thetaR_ = 0.0;
  double shift_[3], width_[3];
};
}  // namespace hp::reference
