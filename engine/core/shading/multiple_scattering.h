#pragma once
// Contract: the per-material tables of hairpipe's multiple-scattering term for the physical fibre model
// (docs/THEORY.md §6: Zinke et al. 2008's dual scattering; docs/SHADING.md "Multiple scattering"), in
// double precision, at `entries` sines of theta evenly spaced over [-1, 1] (the ends evaluated at
// +-kEdgeSine, where cos theta > 0):
//  - forwardAlbedo a_f: the fraction of the light arriving at theta that one fibre sends on into the far
//    half of the azimuths (|phi| > pi/2), per RGB: sum_p [int M_p cos theta_i d theta_i] [int_far N_p d phi]
//    (the white furnace restricted to forward scattering; by reciprocity the same for either direction);
//    backAlbedo a_b the same over the near half (|phi| < pi/2); a_f + a_b is the white furnace; both are
//    clamped to [0, 1] (the quadrature of a lobe far narrower than its panels overshoots: beta_R 0.01 deg
//    gave a_f = 5.6, and exp(tau (a_f - 1)) overflowed in the shader);
//  - the azimuthal means of the lobes, (1/2 pi) int N_p d phi, for R (colourless), TT and TRT + residual:
//    a fibre lit from every azimuth at once (light spread around it by the hair in front) sends
//    sum_p M_p x mean N_p toward the viewer, per unit light (what S cos theta_i is for one direction);
//  - the local back-scattering of the hair around a fibre (Zinke's A_b): light that crosses n >= 1 fibres
//    forward, is scattered back by one and crosses n fibres forward again on its way out. Energy
//    backScatter = A_1 + A_3 = a_b a_f^2 / (1 - a_f^2) + a_b^3 a_f^2 / (1 - a_f^2)^3 per RGB (at most 1);
//    its longitudinal spread is
//    that of A_1's paths: each scattering event p moves theta_i + theta_r by the lobe's shift s_p with
//    variance v_p (physical_terms.h), so the 2n + 1 events of a path add up, n being geometric with ratio
//    a_f^2. backShift and backWidth are the mean and the standard deviation of theta_i + theta_r for the
//    back-scattered light (radians; A_b-weighted over RGB). The device form of that lobe, normalised
//    against cos theta_r for every theta_i, is the physical M texture's fourth channel (lut_physical.cpp).
// Deterministic; ~3 ms for 32 entries.
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/shading/material.h"

namespace hp {
struct MultipleScatteringTables {
  std::vector<glm::dvec3> forwardAlbedo, backAlbedo;
  std::vector<double> meanR;
  std::vector<glm::dvec3> meanTT, meanTRT;  // TRT: with the residual p >= 3 (it shares M_TRT)
  std::vector<glm::dvec3> backScatter;      // A_b
  std::vector<double> backShift, backWidth;
};

inline constexpr double kEdgeSine = 0.999;
MultipleScatteringTables multipleScatteringTables(const HairMaterial& m, int entries);

// The mean fraction of a uniform sky that a visible fibre of an optically thick head of hair receives when
// the hair on the way passes a_f of the light on forward (dual scattering; docs/SHADING.md "Ambient"):
// (1 - k ln(1 + 1/k)) / 2 per RGB, k = 1 - a_f averaged over the sky's directions (weight cos^2 theta d
// theta: solid angle times the fibre's cross-section). k = 1 (no forward scattering) gives single
// scattering's (1 - ln 2) / 2, RENDER_HAIR_SKY_VISIBILITY; k -> 0 gives 1/2, the open half of the sky.
glm::dvec3 skyVisibility(const MultipleScatteringTables& t);
// a_f averaged over a uniform sky's directions (weight cos^2 theta d theta), per RGB: what skyVisibility
// and the hair's transmittance to and from the skin (with dual scattering) take for light of any direction.
glm::dvec3 meanForwardAlbedo(const MultipleScatteringTables& t);

// The back-scattered lobe's (shift, width) at sin theta, linear between the tables' entries (as the shader
// reads the other tables); what the M texture's back-lobe columns are built from.
glm::dvec2 backLobeAt(const MultipleScatteringTables& t, double sinTheta);
}  // namespace hp
