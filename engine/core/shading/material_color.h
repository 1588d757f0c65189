#pragma once
// Contract: converts a perceived hair colour into the Marschner absorption coefficient sigma_a.
//
// Meaning of the colour (documented choice): rgb is the fraction of light that survives ONE straight
// pass through the centre of the fibre at normal incidence (theta_d = 0, h = 0, chord = 2 radii),
// Fresnel ignored. With docs/THEORY.md §3.4's T = exp(-2 sigma_a' cos gamma_t) at gamma_t = 0 that gives
//     sigma_a = -ln(c) / 2     (per unit fibre radius).
// Why this and not Chiang et al. 2016's sigma_a = (ln c / f(beta_n))^2: that fit targets the
// multiple-scattering colour of a rough d'Eon/Chiang fibre and depends on its azimuthal roughness
// beta_n, which the Marschner model does not have. The single-pass transmittance is exact for this
// model's TT lobe at its peak, so the colour a user picks is the colour of the forward-scattering
// highlight. The default brown (0.55, 0.91, 1.78) corresponds to c = (0.333, 0.162, 0.028).
// Each component must be finite and in (0, 1]; otherwise hp::Error naming "color".
#include <glm/glm.hpp>

namespace hp {
glm::dvec3 absorptionFromColor(glm::dvec3 rgb);
glm::dvec3 colorFromAbsorption(glm::dvec3 sigmaA);
}  // namespace hp
