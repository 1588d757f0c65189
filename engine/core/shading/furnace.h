#pragma once
// Contract: the white-furnace integral of a fibre model, per RGB channel: for one outgoing direction
// (given by sin theta_r; the integral does not depend on the outgoing azimuth),
//   W = int over the sphere of incoming L of S(L, V) cos(theta_i) d omega_i,
// d omega = cos theta_i d theta_i d phi. An energy-conserving fibre has W <= 1, = 1 without absorption.
// Computed by composite Gauss-Legendre quadrature in double precision:
//  - Physical: S cos theta_i = sum_p M_p(theta_i, theta_r) N_p(phi, theta_r) exactly, so W is
//    sum_p [int M_p cos theta_i d theta_i] [int N_p d phi], each integral numerical (the model's own
//    identities are not assumed);
//  - Marschner (the paper's model, docs/THEORY.md §3): S does not factor (1/cos^2 theta_d), so W is a
//    2D quadrature over (theta_i, phi) of the exact S; `panels` 8-node panels per axis.
#include <array>

#include <glm/glm.hpp>

#include "engine/core/shading/fibre_model.h"

namespace hp {
glm::dvec3 whiteFurnace(FibreModel model, double sinThetaR, const HairMaterial& m, int panels = 64);

// W restricted to incoming azimuths |phi| in [phiLo, phiHi] relative to the outgoing one: [0, pi/2] is the
// light from the viewer's side of the fibre (R and TRT mostly), [pi/2, pi] from behind it (TT).
glm::dvec3 whiteFurnaceOver(FibreModel model, double sinThetaR, const HairMaterial& m, double phiLo, double phiHi,
                            int panels);

// The physical model's W restricted to incoming azimuths |phi| in [phiLo, phiHi] (whiteFurnace: [0, pi]);
// [pi/2, pi] is the light one fibre scatters on forward (engine/core/shading/multiple_scattering.h).
glm::dvec3 physicalFurnaceOver(double sinThetaR, const HairMaterial& m, double phiLo, double phiHi, int panels);
// The same per lobe (R, TT, TRT with the residual, which shares its M): the terms the sum above adds.
std::array<glm::dvec3, 3> physicalLobeFurnaceOver(double sinThetaR, const HairMaterial& m, double phiLo,
                                                  double phiHi, int panels);

// The fibre's albedo under a uniform white sky of radiance 1, seen from a uniformly random direction:
// W(theta_r) averaged over the sphere of outgoing directions, (1/2) int W cos(theta_r) d theta_r over
// [-90, 90] deg (16 Gauss-Legendre nodes). What the real-time ambient term multiplies by the sky's
// radiance; the reference's sky returns exactly this from an unoccluded fibre. Quadrature: 16 panels
// for the physical model (~5 ms), 4 for Marschner (~40 ms; within 0.5% of 64 panels, default brown).
glm::dvec3 skyAlbedo(FibreModel model, const HairMaterial& m);
// The part of it from incoming azimuths |phi| in [phiLo, phiHi] (skyAlbedo: [0, pi]): what an environment's
// light from the viewer's side ([0, pi/2]) and from behind the fibre ([pi/2, pi]) is multiplied by
// (docs/SHADING.md "Environment").
glm::dvec3 skyAlbedoOver(FibreModel model, const HairMaterial& m, double phiLo, double phiHi);
}  // namespace hp
