#pragma once
// Contract: importance sampling of incoming directions at a fibre of the physical model
// (engine/core/shading/physical_terms.h) for the path tracer, by the model's own structure, so that
// S cos(theta_i) / pdf stays near the fibre's albedo (exactly 1 for a white fibre, whatever the
// directions; for coloured hair it varies with the direction by the lobes' colours; the lobe-shaped mixture of fibre_sampling.h had heavy tails there, which made many-bounce
// paths in light hair noisy beyond use). One sample:
//   an offset h: one node of N_p's h quadrature (the same nodes, chosen by their weights);
//   a lobe p (R, TT, TRT or the residual p >= 3) by A_p(h)'s mean over r, g, b;
//   theta_i from the lobe's longitudinal M_p exactly (d'Eon's lobe about the shifted specular cone;
//   the residual takes TRT's);
//   phi = Phi(p, gamma_o, gamma_t) plus a Gaussian of width beta_N (the residual: uniform).
// pdf() is that mixture's exact solid-angle density: sum_p M_p(theta_i) Ntilde_p(phi), with Ntilde_p the
// h-quadrature of P(p | h) times the azimuthal Gaussian.
#include <array>
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/shading/material.h"
#include "samples/tools/reference/sampling.h"

namespace hp::reference {
class PhysicalFibreSampler {
 public:
  PhysicalFibreSampler(const glm::dvec3& tangent, const glm::dvec3& toEye, const HairMaterial& material);
  glm::dvec3 sample(Sampler& rng) const;    // unit direction toward the light
  double pdf(const glm::dvec3& dir) const;  // solid-angle density of sample()

 private:
  struct Node {
    double gammaO = 0.0, gammaT = 0.0;
    std::array<double, 4> lobe{};  // P(p | h), p = R, TT, TRT, residual
  };
  double sampleSinThetaI(int p, double u1, double u2) const;
  double azimuthDensity(int p, double phi) const;  // Ntilde_p(phi)

  FibreFrame frame_;
  HairMaterial material_;
  std::vector<Node> nodes_;
  std::vector<double> weights_, cumulative_;  // node weights (sum 1) and their running sums
};
}  // namespace hp::reference
