#pragma once
// Contract: the hair fibre material of the Marschner model (docs/THEORY.md §3.6) and of the physical
// model (§4: the same eta, absorption, alpha_R, beta_R, plus the azimuthal width betaN). Angles are stored in
// radians; absorption sigma_a is per unit fibre radius, per RGB channel. validate() throws hp::Error
// naming the first bad field (NaN, negative, or outside the physically meaningful range).
#include <glm/glm.hpp>

namespace hp {
struct HairMaterial {
  double eta = 1.55;                                  // index of refraction of the fibre
  glm::dvec3 absorption = {0.55, 0.91, 1.78};         // sigma_a per unit radius (brown)
  double alphaR = glm::radians(-7.5);                 // longitudinal shift of R (radians)
  double betaR = glm::radians(7.5);                   // longitudinal width of R (radians)
  double kG = 0.5;                                    // caustic glint scale
  double wc = glm::radians(15.0);                     // caustic azimuthal width (radians)
  double dEta = 0.3;                                  // caustic fade range for eta'
  double dhM = 0.5;                                   // caustic maximum h range
  // Physical model only (docs/THEORY.md §4.2): std. dev. of the azimuthal scattering lobe D (radians).
  double betaN = glm::radians(10.0);
  // Per-strand variation of the cuticle tilt (radians, [0, 10 deg]): each render strand shades with alphaR + t,
  // t uniform in [-tiltVariation, tiltVariation) from the strand's key (shaders/shared/strands.h strandTilt),
  // so neighbouring strands' highlights sit at slightly different places along the hair. The physical and
  // direct modes and the reference take it; the paper and float LUT modes ignore it.
  double tiltVariation = glm::radians(2.0);
  // Per-strand variation of the longitudinal roughness (0 or [0.01, 0.25]): each render strand shades with betaR x s,
  // s one of 7 levels evenly spaced over [1 - roughnessVariation, 1 + roughnessVariation], picked by the strand's
  // key (shaders/shared/strands.h strandRoughness), so neighbouring strands' highlights differ in width and peak.
  // The physical mode reads a layer of its M texture per level (docs/SHADING.md "Per-strand roughness"), the
  // direct mode scales beta_R; the reference takes it; the paper and float LUT modes ignore it.
  double roughnessVariation = 0.15;

  void validate() const;
  bool operator==(const HairMaterial&) const = default;
};
}  // namespace hp
